#!/bin/sh
# Notes §2.10, the heavy symmetric top (gyroscope I1 = 0.02, I3 = 0.01 kg m², M g h
# = 0.98 N m, ω3 = 100 rad/s at θ = 60°) started at the slow steady precession:
# θ stays 60°, precession.steady_slow = 0.99048 rad/s (gyroscopic approximation
# M g h/(I3 ω3) = 0.98067 is 1 % low).
# Usage: MECHD_URL=http://host:port rigid_top.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rigid/top" --json '{
  "I1": 0.02,
  "I3": 0.01,
  "mass": 1.0,
  "distance": 0.1,
  "theta": 1.0471975511965976,
  "phi_dot": 0.9904754154868383,
  "psi_dot": 99.50476229225659,
  "t_end": 4,
  "samples": 5,
  "integrator": {
    "accuracy": "precise"
  },
  "cost": false
}'
