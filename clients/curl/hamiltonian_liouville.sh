#!/bin/sh
# Notes chapter 5, Liouville's theorem: a loop in the 4-D phase space of the
# Hénon–Heiles system keeps its symplectic area 0.00025π = 7.854e-4 (runs[0].area)
# and the tangent map keeps det 1, however the flow deforms it.
# Usage: MECHD_URL=http://host:port hamiltonian_liouville.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/hamiltonian/liouville" --json '{
  "system": {
    "name": "henon_heiles"
  },
  "curve": {
    "type": "ellipse",
    "center": [0.0, 0.1, 0.35, 0.1],
    "u": [0.02, 0.0, 0.0, 0.01],
    "w": [0.0, 0.015, 0.02, 0.0]
  },
  "t_end": 20,
  "samples": 3,
  "integrators": [
    {
      "method": "gauss6",
      "dt": 0.02
    }
  ],
  "cost": false
}'
