#!/bin/sh
# Effective gravity at 45° latitude: the centrifugal term W²R cos λ tilts the plumb
# line about 0.1° towards the equator and lowers g by W²R/2 ≈ 1.7 cm/s².
# Usage: MECHD_URL=http://host:port earth_gravity.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/earth/gravity" --json '{
  "latitude_deg": 45
}'
