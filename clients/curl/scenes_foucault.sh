#!/bin/sh
# Notes §1.4, the Foucault pendulum at 32° latitude (67 m, 200 swings): the plane
# turns at ω sin λ = 3.864e-5 rad/s clockwise (precession.measured_rate, minus the
# 0.1 % finite-amplitude Airy correction) — a full turn in 45 hours.
# Usage: MECHD_URL=http://host:port scenes_foucault.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/scenes/foucault" --json '{
  "latitude_deg": 32,
  "swings": 200
}'
