#!/bin/sh
# Notes §3.15, the twin paradox: 8 light years to a star at 0.8c and back. The
# Earth twin ages 20 years (total.stay_at_home_time), the astronaut 12
# (total.proper_time); each leg shows the Doppler ticks each twin sees.
# Usage: MECHD_URL=http://host:port relativity_worldline.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/worldline" --json '{
  "units": "years",
  "legs": [
    {
      "velocity": {
        "beta": [0.8, 0, 0]
      },
      "distance": 8
    },
    {
      "velocity": {
        "beta": [-0.8, 0, 0]
      },
      "distance": 8
    }
  ]
}'
