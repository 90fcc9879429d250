#!/usr/bin/python3
"""Compute lorentz_boost.pg's answer tables with mechd (WeBWorK's PG runs in a Safe
compartment with no network and no subprocess, so mechd is used when the problem is
written). Prints the Perl lines to paste into the PG file:

    MECHD_EVAL=build/mechd-eval python3 docs/grading/webwork/make_tables.py

For each beta: the Lorentz factor and the boosted coordinates (ct', x') of the event
(ct, x) = (1 m, 0) seen from a frame moving at beta along x (/v1/relativity/boost), and
mechd's recommended relative tolerance (the PG tolerance must not be tighter).
"""
import json
import os
import subprocess

BETAS = [0.28, 0.6, 0.8, 0.96]


def boost(beta):
    env = {"operation": "/v1/relativity/boost",
           "request": {"vectors": [[1, 0, 0, 0]], "velocity": {"beta": [beta, 0, 0]}}}
    out = subprocess.run([os.environ.get("MECHD_EVAL", "mechd-eval")], input=json.dumps(env).encode(),
                         capture_output=True, timeout=30, check=True).stdout
    return json.loads(out)


def tables():
    rows = [boost(b) for b in BETAS]
    fmt = lambda xs: ", ".join(repr(float(x)) for x in xs)
    return "\n".join([
        "@beta  = (%s);" % fmt(BETAS),
        "@gamma = (%s);" % fmt(r["gamma"] for r in rows),
        "@ctp   = (%s);" % fmt(r["vectors"][0][0] for r in rows),
        "@xp    = (%s);" % fmt(r["vectors"][0][1] for r in rows),
    ])


if __name__ == "__main__":
    print(tables())
