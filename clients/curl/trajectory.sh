#!/bin/sh
# An object dropped from 100 m at latitude 32° (notes §1.4) lands about
# 1.86 cm east of the drop point, after sqrt(2h/g) ≈ 4.52 s.
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/trajectory" --json '{
  "particle": {"mass": 1, "position": [0, 0, 100], "velocity": [0, 0, 0]},
  "frame": {"type": "earth", "latitude_deg": 32},
  "forces": [{"type": "uniform_gravity", "g": [0, 0, -9.80665]}],
  "fictitious": ["coriolis"],
  "t_end": 5,
  "samples": 6,
  "stop": {"coordinate": "z", "crosses": 0, "direction": "decreasing"},
  "integrator": {"method": "rk8pd", "rtol": 1e-12, "atol": 1e-12}
}'
