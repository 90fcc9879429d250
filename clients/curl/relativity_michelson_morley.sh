#!/bin/sh
# Notes §3.2: arms of 11 m moving through a supposed ether at 3e4 m/s would differ by
# 110 nm of path (beta^2 L), 0.4 fringes at 550 nm on a 90 degree turn; with the
# Lorentz contraction the shift is 0.
# Usage: MECHD_URL=http://host:port relativity_michelson_morley.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/michelson-morley" --json '{
  "arm_length": 11, "speed": 30000, "wavelength": 5.5e-7
}'
