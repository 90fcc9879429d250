#!/bin/sh
# A 1 kg, 1 m pendulum at 5 J: the area of its phase-space orbit, the action, and the period
# as dA/dE, beside the harmonic approximation.
# Usage: MECHD_URL=http://host:port hamiltonian_phase_area.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/hamiltonian/phase-area" --json '{
  "system": "pendulum", "mass": 1, "length": 1, "energy": 5
}'
