#!/bin/sh
# Notes §0.5 (homework): the axes turned 120° about (1,1,1) go x → y → z → x.
# The answer's passive matrix is the cyclic permutation [[0,1,0],[0,0,1],[1,0,0]],
# the quaternion (1,1,1,1)/2 and the z-x-z Euler angles (π/2, π/2, 0).
# Usage: MECHD_URL=http://host:port rotation_convert.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rotation/convert" --json '{
  "axis_angle": {
    "axis": [1, 1, 1],
    "angle": 2.0943951023931953
  }
}'
