#!/bin/sh
# Mercury's perihelion in the Schwarzschild metric (notes chapter 4): 10 orbits
# integrated; precession.arcsec_per_century.measured ≈ 42.98″ per century — the
# famous 43″ (first order 6πGM/(c²a(1−e²)) per orbit).
# Usage: MECHD_URL=http://host:port gr_geodesic.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/gr/geodesic" --json '{
  "M": "sun",
  "kind": "timelike",
  "initial": {
    "semi_major_axis": 57909050000.0,
    "eccentricity": 0.20563593
  },
  "orbits": 10,
  "samples": 3,
  "integrator": {
    "accuracy": "precise"
  },
  "cost": false
}'
