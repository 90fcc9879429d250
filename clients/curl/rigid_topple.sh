#!/bin/sh
# Notes §2.11 HW 4: a 10 cm cube balanced on an edge falls onto a face at
# w = sqrt((3g/(2l)) (sqrt 2 - 1)) = 7.81 rad/s with the edge held, and
# sqrt((12g/(5l)) (sqrt 2 - 1)) = 9.88 rad/s on a frictionless floor.
# Usage: MECHD_URL=http://host:port rigid_topple.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rigid/topple" --json '{
  "width": 0.1
}'
