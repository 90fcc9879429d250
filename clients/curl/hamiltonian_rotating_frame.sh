#!/bin/sh
# A puck at rest 2 m from the axis of a table turning at 0.5 rad/s: H_rot = -1/2 m w^2 r^2
# = -0.5 J while the inertial energy is +0.5 J (H_rot = E - omega.L).
# Usage: MECHD_URL=http://host:port hamiltonian_rotating_frame.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/hamiltonian/rotating-frame" --json '{
  "mass": 1, "omega": [0, 0, 0.5], "position": [2, 0, 0], "velocity": [0, 0, 0]
}'
