#!/bin/sh
# Notes §3, π⁰ decay: at rest the π⁰ (134.98 MeV) goes into two back-to-back
# photons of m/2 = 67.49 MeV each (rest_frame.energies).
# Usage: MECHD_URL=http://host:port relativity_kinematics_decay.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/kinematics/decay" --json '{
  "parent": {
    "particle": "pi0"
  },
  "daughters": ["photon", "photon"]
}'
