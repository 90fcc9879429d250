#!/bin/sh
# Inertia tensor of a unit cube about its corner (notes §2.4); principal
# moments Ms²·{1/6, 11/12, 11/12}. Usage: MECHD_URL=http://host:port inertia.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rigid/inertia" --json '{
  "bodies": [{"shape": "box", "mass": 1, "size": [1, 1, 1], "position": [0.5, 0.5, 0.5]}],
  "origin": [0, 0, 0],
  "omega": [0, 0, 1]
}'
