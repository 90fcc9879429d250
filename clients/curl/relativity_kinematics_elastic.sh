#!/bin/sh
# Notes §3, problem 16: a 500 MeV proton scattered through 30° in the lab by a
# proton at rest keeps T' = T cos²θ/(1 + T sin²θ/(2m)) = 351.58 MeV; the recoil
# leaves at 53.83°, so the opening angle is 83.8° (90° only non-relativistically).
# Usage: MECHD_URL=http://host:port relativity_kinematics_elastic.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/kinematics/elastic" --json '{
  "projectile": {"particle": "proton", "kinetic_energy": 500},
  "target": "proton",
  "angle_deg": 30
}'
