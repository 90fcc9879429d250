#!/bin/sh
# Notes §3, π⁰ decay: at rest the π⁰ (134.98 MeV) goes into two back-to-back
# photons of m/2 = 67.49 MeV each (rest_frame.energies).
# Usage: MECHD_URL=http://host:port relativity_kinematics_decay.sh
exec curl -s "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/kinematics/decay" --json '{
  "parent": {
    "particle": "pi0"
  },
  "daughters": ["photon", "photon"]
}'
