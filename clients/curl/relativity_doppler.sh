#!/bin/sh
# Notes §3.14-3.15: the astronaut's clock (one tick a year) receding at 0.8c is seen
# on Earth at √((1−β)/(1+β)) = 1/3 tick a year (doppler_factor 0.3333).
# Usage: MECHD_URL=http://host:port relativity_doppler.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/doppler" --json '{
  "source_velocity": {
    "beta": [0.8, 0, 0]
  },
  "arrival_direction": [-1, 0, 0],
  "frequency": 1
}'
