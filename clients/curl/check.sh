#!/bin/sh
# Grading: is a student's 0.1667 kg m² the smallest principal moment of a unit cube
# about its corner (exactly 1/6)? With 3 significant figures: correct = true; the
# answer also gives the expected value, the errors and a recommended tolerance.
# Usage: MECHD_URL=http://host:port check.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/check" --json '{
  "operation": "/v1/rigid/inertia",
  "request": {
    "bodies": [
      {
        "shape": "box",
        "mass": 1,
        "size": [1, 1, 1],
        "position": [0.5, 0.5, 0.5]
      }
    ],
    "origin": [0, 0, 0]
  },
  "answer": {
    "pointer": "/principal/moments/0",
    "value": 0.1667
  },
  "tolerance": {
    "significant_figures": 3
  }
}'
