#!/usr/bin/python3
"""workprecision_scipy.py -- the baseline a Python user would pick: SciPy's
solve_ivp with DOP853 (Hairer-Norsett-Wanner's 8(5,3) Dormand-Prince pair) on
the same Kepler scene as bench/bench_workprecision.c, timed with
time.process_time() around solve_ivp only.

Run by bench_workprecision (never by the tests) with Debian's /usr/bin/python3
(python3-scipy; scripts/install-deps.sh --bench installs it):

    workprecision_scipy.py GM T_END Q0x Q0y Q0z V0x V0y V0z REPEATS RTOL [RTOL ...]

Scene: q'' = -GM q / |q|^3 in 3-D (the same 6-dimensional state as the C
program), t from 0 to T_END, rtol = atol = RTOL. One output line per RTOL:

    dop853 rtol=<r> steps=<n> nfev=<n> cpu=<s> max_rel_dE=<x> final=<6 reals>

The scene set (bench_workprecision's "scene set" section):

    workprecision_scipy.py --scene NAME T_END CAP_S Y0_1 .. Y0_n -- RTOL [RTOL ...]

    workprecision_scipy.py --scene NAME --method M T_END CAP_S Y0_1 .. Y0_n -- RTOL ...

runs solve_ivp's method M (DOP853, the default, LSODA or Radau) instead
(bench_chooser_regret); its nfev adds n evaluations per Jacobian.

NAME: kepler (GM = 1, y = (q, v) in 3-D), oscillator (q'' = -q in 3-D),
rotosc (that oscillator seen from a frame turning at 0.3 rad/s about z),
lorentz (unit charge and mass in B = (0, 0, 1)), pendulum (m = l = 1,
g = 9.80665, y = (theta, p)),
rigid (Euler's equations, moments 1, 2, 3, y = omega), henon_heiles (y =
(x, y, p_x, p_y)), falling (100 m at 32 deg N with Coriolis, y = (q, v) in
east-north-up), top (the heavy symmetric top in Euler angles, y = (theta,
phi, psi, theta')). One line per RTOL (rtol = atol), loose to tight,
stopping after a run costing more than CAP_S seconds:

    dop853 rtol=<r> nfev=<n> cpu=<s> final=<n reals>

The C program computes the error of `final` against its reference.

cpu is the minimum over REPEATS runs (the runs are deterministic, so every
repeat gives the same numbers). max_rel_dE is max |E - E0| / |E0| over every
accepted step (solve_ivp returns them all without t_eval); the C program
computes the position error of `final` against Kepler's equation with the
same code it uses for its own runs, so both sides are measured alike.
"""
import math
import sys
import time

import warnings

import numpy as np
from scipy.integrate import solve_ivp


def rhs_of(name):
    if name == "kepler":
        def f(t, y):
            x, yy, z, vx, vy, vz = y
            r2 = x * x + yy * yy + z * z
            k = -1.0 / (r2 * math.sqrt(r2))
            return [vx, vy, vz, k * x, k * yy, k * z]
    elif name == "oscillator":
        def f(t, y):
            return [y[3], y[4], y[5], -y[0], -y[1], -y[2]]
    elif name == "rigid":
        def f(t, w):
            return [(2.0 - 3.0) / 1.0 * w[1] * w[2], (3.0 - 1.0) / 2.0 * w[2] * w[0],
                    (1.0 - 2.0) / 3.0 * w[0] * w[1]]
    elif name == "falling":
        # Earth frame (east, north, up), 32 deg N, Coriolis only
        W, lat = 7.2921159e-5, math.radians(32.0)
        wy, wz = W * math.cos(lat), W * math.sin(lat)

        def f(t, y):
            vx, vy, vz = y[3], y[4], y[5]
            return [vx, vy, vz, -2.0 * (wy * vz - wz * vy), -2.0 * wz * vx,
                    -9.80665 + 2.0 * wy * vx]
    elif name == "top":
        # heavy symmetric top in Euler angles, y = (theta, phi, psi, theta')
        I1, I3, mgl = 0.02, 0.01, 0.980665
        th0 = math.pi / 3
        ppsi = I3 * (99.5 + 0.99 * math.cos(th0))
        pphi = I1 * 0.99 * math.sin(th0) ** 2 + ppsi * math.cos(th0)

        def f(t, y):
            s, c = math.sin(y[0]), math.cos(y[0])
            phid = (pphi - ppsi * c) / (I1 * s * s)
            return [y[3], phid, ppsi / I3 - phid * c,
                    (I1 * phid * phid * s * c - ppsi * phid * s + mgl * s) / I1]
    elif name == "rotosc":
        # the isotropic oscillator q'' = -q seen from a frame turning at
        # 0.3 rad/s about z: Coriolis -2 w x v and centrifugal -w x (w x q)
        w = 0.3

        def f(t, y):
            x, yy, z, vx, vy, vz = y
            return [vx, vy, vz, -x + 2.0 * w * vy + w * w * x, -yy - 2.0 * w * vx + w * w * yy,
                    -z]
    elif name == "lorentz":
        # a unit charge and mass in B = (0, 0, 1): v' = v x B
        def f(t, y):
            return [y[3], y[4], y[5], y[4], -y[3], 0.0]
    elif name == "pendulum":
        # the plane pendulum, m = l = 1, g = 9.80665, y = (theta, p)
        def f(t, y):
            return [y[1], -9.80665 * math.sin(y[0])]
    elif name == "henon_heiles":
        def f(t, y):
            x, yy, px, py = y
            return [px, py, -x - 2.0 * x * yy, -yy - x * x + yy * yy]
    else:
        return None
    return f


def scene_main(argv):
    warnings.filterwarnings("ignore", message="At least one element of `rtol` is too small")
    method = "DOP853"
    if "--method" in argv:  # DOP853 (default), LSODA or Radau
        k = argv.index("--method")
        method = argv[k + 1]
        argv = argv[:k] + argv[k + 2:]
    sep = argv.index("--")
    name, t_end, cap = argv[2], float(argv[3]), float(argv[4])
    y0 = [float(a) for a in argv[5:sep]]
    rtols = [float(a) for a in argv[sep + 1:]]
    f = rhs_of(name)
    if f is None:
        print("unknown scene %s" % name)
        return 2
    for rtol in rtols:
        c0 = time.process_time()
        sol = solve_ivp(f, (0.0, t_end), y0, method=method, rtol=rtol, atol=rtol)
        cpu = time.process_time() - c0
        if sol.status != 0:
            print("%s rtol=%.3g failed: %s" % (method.lower(), rtol, sol.message), flush=True)
            break
        final = " ".join(repr(float(v)) for v in sol.y[:, -1])
        # nfev: right-hand sides; Radau's and LSODA's Jacobians (njev, by finite
        # differences: n evaluations each) are added
        nfev = sol.nfev + (sol.njev or 0) * len(y0)
        print("%s rtol=%.17g nfev=%d cpu=%.6f final=%s" % (method.lower(), rtol, nfev, cpu,
                                                            final), flush=True)
        if cpu > cap:
            break
    return 0


def main(argv):
    if len(argv) > 1 and argv[1] == "--scene":
        return scene_main(argv)
    if len(argv) < 11:
        sys.stderr.write(__doc__)
        return 2
    gm = float(argv[1])
    t_end = float(argv[2])
    y0 = [float(a) for a in argv[3:9]]
    repeats = max(1, int(argv[9]))
    rtols = [float(a) for a in argv[10:]]

    def rhs(t, y):
        x, yy, z, vx, vy, vz = y
        r2 = x * x + yy * yy + z * z
        k = -gm / (r2 * math.sqrt(r2))
        return [vx, vy, vz, k * x, k * yy, k * z]

    def energy(y):
        q = y[0:3]
        v = y[3:6]
        return 0.5 * np.sum(v * v, axis=0) - gm / np.sqrt(np.sum(q * q, axis=0))

    e0 = energy(np.array(y0).reshape(6, 1))[0]
    for rtol in rtols:
        best = math.inf
        sol = None
        for _ in range(repeats):
            c0 = time.process_time()
            sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=rtol, atol=rtol)
            best = min(best, time.process_time() - c0)
        if sol.status != 0:
            print("dop853 rtol=%.3g failed: %s" % (rtol, sol.message), flush=True)
            continue
        drift = float(np.max(np.abs(energy(sol.y) - e0)) / abs(e0))
        final = " ".join(repr(float(v)) for v in sol.y[:, -1])
        print("dop853 rtol=%.17g steps=%d nfev=%d cpu=%.6f max_rel_dE=%.6e final=%s"
              % (rtol, sol.t.size - 1, sol.nfev, best, drift, final), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
