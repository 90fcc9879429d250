#!/bin/sh
# Three equal masses (1 kg) between two walls, four equal springs (1 N/m):
# the chain's closed form w_j = 2 sqrt(k/m) sin(j pi/8) gives /modes/0/omega =
# 0.7654, /modes/1/omega = sqrt 2 and /modes/2/omega = 1.8478 rad/s, with the
# mass-normalised shapes (1/2, sqrt2/2, 1/2), (sqrt2/2, 0, -sqrt2/2), (-1/2, sqrt2/2, -1/2).
# Usage: MECHD_URL=http://host:port coupled_oscillations.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -s -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/coupled-oscillations" --json '{
  "system": {"name": "spring_chain", "masses": [1, 1, 1], "springs": [1, 1, 1, 1]}
}'
