#!/bin/sh
# Notes §2.9: a torque-free symmetric top, I1 = I2 = 1, I3 = 2, omega = (1, 0, 2).
# omega goes round the symmetry axis at the notes' Omega = (I3 - I1)/I1 w3 =
# 2 rad/s (body cone atan(1/2)); the axis goes round L at |L|/I1 = sqrt 17 rad/s.
# Usage: MECHD_URL=http://host:port rigid_free_symmetric_top.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rigid/free-symmetric-top" --json '{
  "moments": [1, 2],
  "omega": [1, 0, 2]
}'
