#!/bin/sh
# Notes §3, Compton scattering: a 70.9 pm X-ray scattered at 90° off an electron
# comes out 2.426 pm longer (wavelength_shift = h/(m c), the Compton wavelength).
# Usage: MECHD_URL=http://host:port relativity_kinematics_compton.sh
exec curl -s "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/kinematics/compton" --json '{
  "wavelength": 7.09e-11,
  "angle_deg": 90
}'
