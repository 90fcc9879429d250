#!/bin/sh
# Notes §1.4, deflection of a falling object: dropped from 100 m at 32° latitude it
# lands about 1.9 cm east (numerical.east ≈ 0.01862 m = (ω cos λ/3)√(8h³/g)).
# Usage: MECHD_URL=http://host:port scenes_falling_object.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/scenes/falling-object" --json '{
  "height": 100,
  "latitude_deg": 32,
  "cost": false
}'
