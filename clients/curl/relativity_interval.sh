#!/bin/sh
# Notes §3.4, length contraction: a 1 m stick at rest, its ends marked at the same
# t' in a frame moving at β = 0.6. The two marks are 0.8 m = l/γ apart (s2 = 0.64,
# proper_length 0.8, spacelike).
# Usage: MECHD_URL=http://host:port relativity_interval.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/interval" --json '{
  "events": [[0, 0, 0, 0], [0.6, 1, 0, 0]]
}'
