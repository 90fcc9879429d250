#!/bin/sh
# The Dzhanibekov flip (notes §2.10, stability): a torque-free body with moments
# (1, 2, 3) spun near its intermediate axis. omega[1] changes sign again and again;
# flip.exact_flip_interval = 2K(m)/λ ≈ 13.95 s from the Jacobi elliptic solution.
# Usage: MECHD_URL=http://host:port rigid_rotate.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rigid/rotate" --json '{
  "moments": [1, 2, 3],
  "omega": [0.05, 1, 0.05],
  "t_end": 60,
  "samples": 7,
  "integrator": {
    "accuracy": "precise"
  },
  "cost": false
}'
