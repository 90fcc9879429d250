#!/bin/sh
# Notes §3.4, the muon at beta = 0.9999 with tau = 2 us: gamma = 70.71, E = 7.47 GeV,
# c tau = 600 m but a lab lifetime gamma tau = 141 us and decay length 42.4 km; m v^2/2
# beside the exact T is 99 % low.
# Usage: MECHD_URL=http://host:port relativity_particle.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/particle" --json '{
  "particle": "mu-", "beta": 0.9999, "proper_lifetime": 2e-6
}'
