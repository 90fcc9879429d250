#!/bin/sh
# An electron at beta = 0.6 in a 1 T field along z, 1 mm off the axis: L = -mc^2/gamma + qA.v,
# canonical momentum gamma m v + qA, H = gamma m c^2 and the Lorentz force q v x B.
# Usage: MECHD_URL=http://host:port relativity_lagrangian.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/lagrangian" --json '{
  "mass": 9.1093837015e-31, "charge": -1.602176634e-19, "velocity": {"beta": [0.6, 0, 0]},
  "fields": {"B": [0, 0, 1], "position": [0, 0.001, 0]}
}'
