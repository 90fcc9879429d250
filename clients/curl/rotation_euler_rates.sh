#!/bin/sh
# A top at theta = 0.6 rad spinning at psi' = 20 rad/s and precessing at
# phi' = 1.5 rad/s: the answer has /omega_body = (phi' sin th sin psi,
# phi' sin th cos psi, phi' cos th + psi') and /omega_space = (psi' sin th sin phi,
# -psi' sin th cos phi, phi' + psi' cos th), and dR/dt = -[omega_body]x R.
# Usage: MECHD_URL=http://host:port rotation_euler_rates.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/rotation/euler-rates" --json '{
  "euler_zxz": [0.3, 0.6, 0.1],
  "rates": [1.5, 0, 20]
}'
