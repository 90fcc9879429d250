#!/bin/sh
# A 1 m steel strip 20 x 5 mm clamped at one end: axial quarter-wave modes from 1262 Hz,
# bending modes from 4.08 Hz (beta L = 1.8751, the root of cos x cosh x = -1).
# Usage: MECHD_URL=http://host:port continuum_rod.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/continuum/rod" --json '{
  "length": 1, "density": 7850, "youngs_modulus": 2e11,
  "section": {"width": 0.02, "height": 0.005}, "ends": "clamped-free"
}'
