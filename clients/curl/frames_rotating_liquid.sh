#!/bin/sh
# Notes §1.5 homework 2: water 5 cm deep in a 10 cm-radius can turning at
# 10 rad/s. Its surface is the paraboloid z = z0 + w² r²/(2g): the rim rises to
# h0 + w² R²/(4g) = 7.55 cm while the centre falls to 2.45 cm; a 10 cm wall
# would spill at sqrt(4 g (H - h0))/R = 14.0 rad/s.
# Usage: MECHD_URL=http://host:port frames_rotating_liquid.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/frames/rotating-liquid" --json '{
  "omega": 10,
  "radius": 0.1,
  "depth": 0.05,
  "container_height": 0.1,
  "radii": [0, 0.05, 0.1]
}'
