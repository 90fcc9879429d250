#!/bin/sh
# Notes §1.5, problem 3: shot straight up to 100 m at 32° latitude, the ball lands
# 7.4 cm WEST of the gun — four times the 1.86 cm eastward drift of a drop.
# Usage: MECHD_URL=http://host:port scenes_vertical_shot.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/scenes/vertical-shot" --json '{
  "height": 100,
  "latitude_deg": 32,
  "cost": false
}'
