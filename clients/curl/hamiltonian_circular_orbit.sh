#!/bin/sh
# Notes ch. 5, motion in a central potential: the circular orbit of the Earth's
# angular momentum about the Sun, r = L^2/(G M m^2) = 1.4967e11 m, with
# omega_r = omega_phi (apsidal angle 180 deg: Kepler orbits close).
# Usage: MECHD_URL=http://host:port hamiltonian_circular_orbit.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/hamiltonian/circular-orbit" --json '{
  "mass": 5.9722e24,
  "angular_momentum": 2.6617e40,
  "gm": 1.32712440018e20
}'
