#!/bin/sh
# Near-circular orbit in V = k r^n with n = 1 (m = 1, r0 = 1, k = 1): the
# radial frequency is sqrt(n + 2) times the orbital one, so /apsidal_angle is
# pi/sqrt(3) = 1.8138 rad (Kepler's n = -1 would give pi, the oscillator pi/2).
# Usage: MECHD_URL=http://host:port small_oscillations.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/small-oscillations" --json '{
  "system": {"name": "central_orbit", "mass": 1, "r0": 1, "terms": [{"k": 1, "n": 1}]}
}'
