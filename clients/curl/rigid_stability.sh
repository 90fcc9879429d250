#!/bin/sh
# Notes §2.10: spin about the intermediate axis of I = (1, 2, 3) is unstable; a
# small tilt grows like exp(√(100/3) t) = exp(5.77 t) at ω = 10 rad/s.
# Usage: MECHD_URL=http://host:port rigid_stability.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rigid/stability" --json '{
  "moments": [1.0, 2.0, 3.0],
  "axis": 2,
  "spin": 10
}'
