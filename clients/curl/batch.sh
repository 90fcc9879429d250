#!/bin/sh
# Several operations in one request, answered in order and independently: the
# cube about its corner (1/6, 11/12, 11/12), 0.5c + 0.5c = 0.8c, and a boost at
# beta = 1, which fails alone (its result is a domain-error problem).
# Usage: MECHD_URL=http://host:port batch.sh
# MECHD_TOKEN, when set, goes as the bearer token (through stdin: not in ps).
printf '%s' "${MECHD_TOKEN:+Authorization: Bearer $MECHD_TOKEN}" |
  exec curl -sS --fail-with-body -H @- "${MECHD_URL:-http://127.0.0.1:8080}/v1/batch" --json '{
  "operations": [
    {
      "operation": "/v1/rigid/inertia",
      "request": {
        "bodies": [
          {
            "shape": "box",
            "mass": 1,
            "size": [1, 1, 1],
            "position": [0.5, 0.5, 0.5]
          }
        ],
        "origin": [0, 0, 0]
      }
    },
    {
      "operation": "/v1/relativity/velocity-addition",
      "request": {
        "velocity": {
          "beta": [0.5, 0, 0]
        },
        "frame_velocity": {
          "beta": [-0.5, 0, 0]
        }
      }
    },
    {
      "operation": "/v1/relativity/boost",
      "request": {
        "vectors": [[1, 0, 0, 0]],
        "velocity": {
          "beta": [1, 0, 0]
        }
      }
    }
  ]
}'
