#!/bin/sh
# A photon rocket reaching beta = 0.6 burns half its mass (m_i/m_f = gamma (1 + beta) = 2);
# Tsiolkovsky's exp(v/c) = 1.82 is 8.9 % low.
# Usage: MECHD_URL=http://host:port relativity_rocket.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/rocket" --json '{
  "beta": 0.6
}'
