#!/bin/sh
# Notes §0.3, passive rotations: the axes turned +90° about z. The old x axis has
# components (0, −1, 0) in the new axes; (0, 2, 3) becomes (2, 0, 3).
# Usage: MECHD_URL=http://host:port rotation_apply.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rotation/apply" --json '{
  "rotation": {
    "axis_angle": {
      "axis": [0, 0, 1],
      "angle": 1.5707963267948966
    }
  },
  "vectors": [[1, 0, 0], [0, 2, 3]]
}'
