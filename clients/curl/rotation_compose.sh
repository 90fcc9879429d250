#!/bin/sh
# Notes §2.6 Euler angles: φ = 0.5 about z, θ = 0.3 about the new x, ψ = 0.2 about
# the new z, composed. matrix = Rψ Rθ Rφ (first entry cos ψ cos φ − cos θ sin φ sin ψ
# = 0.76910) and euler_zxz gives back (0.5, 0.3, 0.2).
# Usage: MECHD_URL=http://host:port rotation_compose.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rotation/compose" --json '{
  "rotations": [
    {
      "axis_angle": {
        "axis": [0, 0, 1],
        "angle": 0.5
      }
    },
    {
      "axis_angle": {
        "axis": [1, 0, 0],
        "angle": 0.3
      }
    },
    {
      "axis_angle": {
        "axis": [0, 0, 1],
        "angle": 0.2
      }
    }
  ]
}'
