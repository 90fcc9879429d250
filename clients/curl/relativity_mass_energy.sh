#!/bin/sh
# The notes' homework: 1366 W/m^2 of sunlight at 1 au means the Sun radiates
# L = 4 pi d^2 F = 3.84e26 W and converts L/c^2 = 4.27e9 kg of rest mass a second.
# Usage: MECHD_URL=http://host:port relativity_mass_energy.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/mass-energy" --json '{
  "flux": 1366,
  "distance": 1.495978707e11
}'
