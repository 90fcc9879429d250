#!/bin/sh
# Two 4-velocities at beta = +-0.6: a.b = -17/8, so one sees the other move with
# gamma_relative = 2.125 (15/17 c by velocity addition).
# Usage: MECHD_URL=http://host:port relativity_dot.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/dot" --json '{
  "a": [1.25, 0.75, 0, 0], "b": [1.25, -0.75, 0, 0]
}'
