#!/bin/sh
# Notes §3.10: 0.5c added to 0.5c is (0.5 + 0.5)/(1 + 0.25) = 0.8c, not c
# (velocity_in_frame.beta = [0.8, 0, 0], gamma 5/3).
# Usage: MECHD_URL=http://host:port relativity_velocity_addition.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/velocity-addition" --json '{
  "velocity": {
    "beta": [0.5, 0, 0]
  },
  "frame_velocity": {
    "beta": [-0.5, 0, 0]
  }
}'
