#!/bin/sh
# GPS: a clock on a circular orbit at r = 26561.75 km against one on the ground.
# Gravity makes it run fast by 45.7 µs/day, its speed slow by 7.2 µs/day:
# clock_comparison.microseconds_per_day.net ≈ +38.5 µs/day.
# Usage: MECHD_URL=http://host:port gr_schwarzschild.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/gr/schwarzschild" --json '{
  "M": "earth",
  "r": 26561750,
  "reference_r": 6371000
}'
