#!/bin/sh
# Notes §1.1-1.2, the second puck: at rest on the floor, seen from a table turning
# at 2 rad/s at r = 0.5 m. Coriolis (−1.2 N) is twice the centrifugal force
# (+0.6 N) and opposite: the net −0.6 N keeps the puck on its apparent circle.
# Usage: MECHD_URL=http://host:port frames_effective_force.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/frames/effective-force" --json '{
  "frame": {
    "omega": [0, 0, 2.0]
  },
  "particle": {
    "mass": 0.3,
    "position": [0, 0.5, 0],
    "velocity": [1.0, 0.0, 0]
  }
}'
