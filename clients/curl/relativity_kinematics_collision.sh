#!/bin/sh
# Notes chapter 3, problem 10: LEP collided 104 GeV electrons with 104 GeV positrons
# head-on: sqrt_s = 208 GeV, all of it available (the centre of mass is at rest).
# Usage: MECHD_URL=http://host:port relativity_kinematics_collision.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/kinematics/collision" --json '{
  "energy_unit": "GeV",
  "beam": {
    "particle": "electron",
    "energy": 104
  },
  "target": {
    "particle": "positron",
    "energy": 104
  }
}'
