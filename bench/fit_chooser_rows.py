#!/usr/bin/env python3
"""fit_chooser_rows.py — the chooser's rows (core/ode/chooser_table.h) fitted
on bench_chooser_regret's hindsight runs of one scene per kind of operation.

  bench/fit_chooser_rows.py OUT_DIR

reads OUT_DIR/chooser_hindsight.tsv (every method swept through the API:
setting, error against the exact reference, evaluations, CPU) and
OUT_DIR/chooser_runs.tsv (the chooser's runs: the span the operation gives
the chooser, its predicted evaluations) and prints, per (rows, method):
  error = A x^a span^b   (least squares in logs over the points between 30x
                          the scene's round-off floor and 1e-2, b kept from
                          the class's rows: one run length per scene here),
  evaluations = B span x^-c + per_sample x samples,
  CPU per evaluation = median of (CPU - the request's fixed 1e-4 s) / evaluations,
and the law's scatter: the largest ratio of measured to law and of law to
measured over the fitted points (the margin must cover the first).
"""
import math
import re
import sys
from collections import defaultdict

out = sys.argv[1]
# scene index -> (rows name, samples, b per method); b: the class's span exponent
SCENES = {
    0: ("central_gravity", 101), 1: ("central_gravity", 101),
    2: ("oscillator", 101), 3: ("oscillator", 101),
    4: ("general", 101), 5: ("general", 101),
    6: ("rigid_body", 11), 7: ("heavy_top", 11), 8: ("geodesic", 11), 9: ("geodesic", 11),
    10: ("hamiltonian_flow", 11), 11: ("hamiltonian_flow", 11),
}
PER_SAMPLE = {"rk8pd": 14, "rkf45": 7, "rkck": 7, "radau15": 52, "gauss6": 30, "yoshida6": 9,
              "rk4": 4}
B_EXP = {"rk8pd": 1.368, "rkf45": 1.311, "rkck": 1.311}  # first_order's span exponents

H = defaultdict(list)
for ln in open(f"{out}/chooser_hindsight.tsv").read().splitlines()[1:]:
    si, m, x, e, ev, cpu = ln.split("\t")
    H[(int(si), m)].append((float(x), float(e), float(ev), float(cpu)))
span = {}
cspan = defaultdict(list)  # the cost law's span, from the runs' predicted evaluations
# the rows the runs were predicted with (B, c, per sample): first_order's before
# the operations had their own; trajectories' cost spans are their own spans
OLD = {"rk8pd": (3.87, 0.100, 14), "rkf45": (1.35, 0.174, 7)}
for ln in open(f"{out}/chooser_runs.tsv").read().splitlines()[1:]:
    f = ln.split("\t")
    si = int(f[0])
    span[si] = float(f[4])
    if si >= 6 and f[2] in OLD and len(sys.argv) > 2 and sys.argv[2] == "--old":
        B0, c0, ps = OLD[f[2]]
        x, pe = float(f[3]), float(f[9])
        cspan[si].append((pe - ps * SCENES[si][1]) / (B0 * x ** -c0))


def lsq(xs, ys):
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    if sxx == 0:
        return my, 0.0
    k = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return my - k * mx, k


for (si, m), pts in sorted(H.items()):
    if si not in SCENES or m not in PER_SAMPLE:
        continue
    rows, ns = SCENES[si]
    sp = span.get(si, 1.0)
    floor = min(p[1] for p in pts)
    use = [p for p in pts if 30 * floor < p[1] < 1e-2 and p[0] > 0]
    if len(use) < 3:
        print(f"/* {rows} {m} scene {si}: {len(use)} points in the law's range */")
        continue
    lx = [math.log(p[0]) for p in use]
    le = [math.log(p[1]) for p in use]
    a0, a = lsq(lx, le)
    lev = [math.log(max(p[2] - PER_SAMPLE[m] * ns, 1.0)) for p in use]
    b0, mc = lsq(lx, lev)
    c = -mc
    b = B_EXP.get(m, 1.0)
    A = math.exp(a0) / sp ** b
    cs = sorted(cspan[si])[len(cspan[si]) // 2] if cspan[si] else sp
    B = math.exp(b0) / cs
    over = max(p[1] / (math.exp(a0) * p[0] ** a) for p in use)
    under = max((math.exp(a0) * p[0] ** a) / p[1] for p in use)
    cpe = sorted(max(p[3] - 1e-4, 1e-9) / p[2] for p in pts if p[2] > 0)
    cpe = cpe[len(cpe) // 2]
    print(f'    {{"{rows}", "{m}", {A:.3g}, {a:.3f}, {b:.3f}, {B:.3g}, {c:.3f}, {PER_SAMPLE[m]}, '
          f'{cpe:.3g}, F, g, Fm}},')
    print(f"    /* scene {si} span {sp:.4g} (cost law's {cs:.4g}): {len(use)} points x = {min(p[0] for p in use):.2g} .. "
          f"{max(p[0] for p in use):.2g}; measured up to {over:.2f}x above the law, "
          f"{under:.2f}x below; floor {floor:.2g} */")
