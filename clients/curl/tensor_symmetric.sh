#!/bin/sh
# Notes ch. 2, the cube rotating about a corner: I = M a^2 [[2/3,-1/4,-1/4],...].
# The answer's /principal/values are M a^2 (1/6, 11/12, 11/12), degenerate, the
# first axis the diagonal (1,1,1)/sqrt(3); /times_vector is I (1,1,1) = (1,1,1)/6.
# Usage: MECHD_URL=http://host:port tensor_symmetric.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/tensor/symmetric" --json '{
  "tensor": [[0.6666666666666666, -0.25, -0.25],
             [-0.25, 0.6666666666666666, -0.25],
             [-0.25, -0.25, 0.6666666666666666]],
  "vector": [1, 1, 1]
}'
