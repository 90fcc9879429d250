#!/bin/sh
# Hénon–Heiles at E = 1/12: 100 crossings of the section x = 0 (p_x > 0) in the
# (y, p_y) plane, starting at (0.1, 0.05); p_x = 0.39349 from H = E, and the
# energy drift stays at round-off.
# Usage: MECHD_URL=http://host:port hamiltonian_poincare.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/hamiltonian/poincare" --json '{
  "system": {
    "name": "henon_heiles"
  },
  "orbits": [
    {
      "energy": 0.08333333333333333,
      "on_section": [0.1, 0.05]
    }
  ],
  "t_max": 5000,
  "max_crossings": 100,
  "cost": false
}'
