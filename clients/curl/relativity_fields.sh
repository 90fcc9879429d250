#!/bin/sh
# Notes, Lorentz transformation of the fields (Heaviside–Lorentz, c = 1), boost at
# β = 0.6 along x: E' = (1, −2, 7.5), B' = (4, 8.5, 6); E² − B² = −63 and E·B = 32
# are the same before and after.
# Usage: MECHD_URL=http://host:port relativity_fields.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/fields" --json '{
  "E": [1, 2, 3],
  "B": [4, 5, 6],
  "velocity": {
    "beta": [0.6, 0, 0]
  }
}'
