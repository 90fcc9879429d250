#!/bin/sh
# A 10 GeV/c proton on a proton at rest (notes §3, kinematics in eV): M² = 2m² +
# 2mE1 gives an invariant mass of only 4539.7 MeV — most of the beam energy goes
# into moving the centre of mass (gamma 2.42).
# Usage: MECHD_URL=http://host:port relativity_kinematics_invariant_mass.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/kinematics/invariant-mass" --json '{
  "momenta": [
    {
      "particle": "proton",
      "momentum": [0, 0, 10000]
    },
    {
      "particle": "proton",
      "momentum": [0, 0, 0]
    }
  ]
}'
