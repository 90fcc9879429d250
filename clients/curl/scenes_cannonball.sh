#!/bin/sh
# Notes §1.4-1.5, cannon balls: fired due east at 500 m/s, 30° elevation, 45° north,
# the ball curves right (south) by 4v0³ω sin λ sin²α cos α/g² = 58.0 m and flies
# 89 m further (notes_due_east).
# Usage: MECHD_URL=http://host:port scenes_cannonball.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/scenes/cannonball" --json '{
  "speed": 500,
  "elevation_deg": 30,
  "azimuth_deg": 0,
  "latitude_deg": 45,
  "cost": false
}'
