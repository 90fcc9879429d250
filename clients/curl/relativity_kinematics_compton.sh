#!/bin/sh
# Notes §3, Compton scattering: a 70.9 pm X-ray scattered at 90° off an electron
# comes out 2.426 pm longer (wavelength_shift = h/(m c), the Compton wavelength).
# Usage: MECHD_URL=http://host:port relativity_kinematics_compton.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/kinematics/compton" --json '{
  "wavelength": 7.09e-11,
  "angle_deg": 90
}'
