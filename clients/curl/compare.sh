#!/bin/sh
# The speed-for-accuracy trade, measured: one Kepler orbit (period 2π) with three
# integrators against the exact solution. rk4 and Störmer–Verlet at dt = π/100 take
# 200 steps each; their errors differ by orders of magnitude (rows[].error).
# Usage: MECHD_URL=http://host:port compare.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/compare" --json '{
  "operation": "/v1/trajectory",
  "request": {
    "particle": {
      "mass": 1,
      "position": [1, 0, 0],
      "velocity": [0, 1, 0]
    },
    "forces": [
      {
        "type": "central_gravity",
        "gm": 1
      }
    ],
    "t_end": 6.283185307179586,
    "samples": 5
  },
  "runs": [
    {
      "accuracy": "machine"
    },
    {
      "method": "rk4",
      "dt": 0.031415926535897934
    },
    {
      "method": "verlet",
      "dt": 0.031415926535897934
    }
  ],
  "cost": false
}'
