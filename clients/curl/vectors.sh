#!/bin/sh
# Notes ch. 0, homework 1: A = x + 3y - 2z, B = 2x + y + z. The answer has
# A.B = 3 at /dot, A x B = (5, -5, -5) at /cross, the component of B along A,
# 3/sqrt(14), at /b_along_a and the angle (70.89 deg) at /angle_deg.
# Usage: MECHD_URL=http://host:port vectors.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/vectors" --json '{
  "a": [1, 3, -2],
  "b": [2, 1, 1]
}'
