#!/bin/sh
# The notes' muon: lifetime 2 µs at rest, beta = 0.9999 relative to the Earth.
# Boosting the decay event (c·tau, 0, 0, 0) into the Earth frame (which moves
# at -beta c relative to the muon) gives ct ≈ 42.4 km, i.e. about 141 µs.
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/relativity/boost" --json '{
  "vectors": [[599.584916, 0, 0, 0]],
  "velocity": {"beta": [-0.9999, 0, 0]}
}'
