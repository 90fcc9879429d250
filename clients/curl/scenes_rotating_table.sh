#!/bin/sh
# Notes §1.1, the first puck: slid across a diameter of a table turning at 1 rad/s,
# it crosses in half a turn; seen from the table it curves and comes back to its
# start (end_rotating = [0, 1, 0]).
# Usage: MECHD_URL=http://host:port scenes_rotating_table.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/scenes/rotating-table" --json '{
  "experiment": "through_center",
  "omega": 1,
  "radius": 1,
  "samples": 5,
  "cost": false
}'
