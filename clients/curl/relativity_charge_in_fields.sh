#!/bin/sh
# A proton released at rest in crossed fields E = 0.8 c (1 T) along y, B = 1 T
# along z: the frame moving with the E x B drift w = E/B = 0.8 c along x
# (gamma 5/3) has no electric field and B' = B/gamma = 0.6 T; there the proton
# circles with radius gamma^2 w m/(q B) = 6.955 m. Answers the state at the lab
# time 100 ns and at the proper time 100 ns.
# Usage: MECHD_URL=http://host:port relativity_charge_in_fields.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -s -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/charge-in-fields" --json '{
  "mass": 1.67262192369e-27,
  "charge": 1.602176634e-19,
  "E": [0, 239833966.4, 0],
  "B": [0, 0, 1],
  "times": [1e-7],
  "proper_times": [1e-7]
}'
