#!/bin/sh
# An electron at beta = 0.6 accelerating at (1e15, 2e15, 0) m/s^2: the force along v is
# gamma^3 m a (longitudinal mass), across v gamma m a (transverse mass).
# Usage: MECHD_URL=http://host:port relativity_force.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/force" --json '{
  "mass": 9.1093837015e-31, "velocity": {"beta": [0.6, 0, 0]}, "acceleration": [1e15, 2e15, 0]
}'
