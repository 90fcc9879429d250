#!/bin/sh
# Notes §1.4, the tides: the Moon's equilibrium tide has a range g h = (3/2)
# GM r²/d³ of about 0.54 m (equilibrium_tide.range; 0.535 m with today's constants).
# Usage: MECHD_URL=http://host:port earth_tides.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/earth/tides" --json '{
  "body": "moon"
}'
