#!/bin/sh
# A failing request: a boost at beta = 1 (the speed of light) is physically
# impossible. mechd answers 422 application/problem+json, type
# /problems/domain-error, with errors[].pointer = "/velocity/beta" naming the field.
# (-i would show the status line and Content-Type.) Like every script here, curl runs
# with --fail-with-body: it prints the problem+json and exits 22 (an HTTP error).
# Usage: MECHD_URL=http://host:port error.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/boost" --json '{
  "vectors": [[1, 0, 0, 0]],
  "velocity": {
    "beta": [1, 0, 0]
  }
}'
