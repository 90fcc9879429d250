#!/bin/sh
# A string under 100 N with 0.01 kg/m, 0.5 m between fixed ends: waves at 100 m/s,
# modes at 100, 200, 300 ... Hz.
# Usage: MECHD_URL=http://host:port continuum_string.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/continuum/string" --json '{
  "tension": 100, "linear_density": 0.01, "length": 0.5
}'
