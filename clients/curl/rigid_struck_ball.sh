#!/bin/sh
# Notes §2.11 HW 3: a pool ball (R = 28.575 mm, 170 g) struck with 0.5 N s rolls
# without slipping at once when struck 2R/5 above its centre (7R/5 = 40 mm above
# the cloth: the rail's height).
# Usage: MECHD_URL=http://host:port rigid_struck_ball.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rigid/struck-ball" --json '{
  "radius": 0.028575,
  "mass": 0.17,
  "impulse": 0.5
}'
