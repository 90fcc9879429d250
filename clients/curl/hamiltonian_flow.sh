#!/bin/sh
# Notes chapter 5, motion in a central potential: Kepler (k = −1, n = −1) with
# p_phi = 1 at r = 1 is the circular orbit: r stays 1, phi = t, period 2π,
# energy −1/2, p_phi conserved (circular_orbit.period = 6.2832).
# Usage: MECHD_URL=http://host:port hamiltonian_flow.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/hamiltonian/flow" --json '{
  "system": {
    "name": "central",
    "mass": 1,
    "k": -1,
    "n": -1
  },
  "q": [1, 0],
  "p": [0, 1],
  "t_end": 6.283185307179586,
  "samples": 5,
  "cost": false
}'
