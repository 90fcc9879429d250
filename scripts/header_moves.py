#!/usr/bin/python3
"""header_moves.py — where each public header of core/ went when
core/include/mech/ was grouped by domain (mech/<domain>/<name>.h, the
answer-shaped layer's under mech/answers/<domain>/), and a rewriter of the
old flat names.

Usage:
  scripts/header_moves.py [FILE ...]   rewrite `mech/<name>.h` (and
        `core/include/mech/<name>.h`) in the given files, or, with no
        argument, in every tracked text file except the operations' data
        (api/ops/**/*.json: their descriptions are served by GET /v1 as they
        stand)
  scripts/header_moves.py --git-mv     move the headers themselves (once)
A branch that still includes the old flat names needs only the first form
after merging main.
"""
import os
import re
import subprocess
import sys

DOMAINS = {
    "base": "budget compensated constants named_bodies status vec",
    "ode": "accuracy chooser chooser_pilot kepler method_choice ode",
    "rotation": "attitude euler_rates rotation vector_algebra",
    "rigid": "inertia mesh rigid_closed_form rigid_problems rigid_rotation stability "
             "sym_tensor top",
    "frames": "chooser_orbit chooser_pendulum closed_form earth effective_force "
              "foucault_first_order frame pendulum reference rotating_liquid scenes "
              "scenes_first_order tides trajectory trajectory_plan trajectory_problem",
    "relativity": "boost charged_lagrangian charged_motion decay_estimate doppler "
                  "elastic_scattering em_fields four_vector interval kinematics "
                  "mass_energy michelson_morley particle_state particles relativistic_force rocket "
                  "telescope velocity_addition worldline",
    "gr": "geodesic gr_units radial_infall schwarzschild",
    "hamiltonian": "apsides circular_orbit coupled_oscillations hamiltonian liouville "
                   "phase_area poincare rotating_hamiltonian small_oscillations "
                   "ham_state_scale:state_scale ham_steady_motion:steady_motion",
    "continuum": "continuum_waves torsion",
    "answers/continuum": "rod_answer",
    "answers/frames": "compare_sweep earth_gravity_answer foucault_scene "
                      "rotating_table_scene tides_answer",
    "answers/gr": "geodesic_run geodesic_setup schwarzschild_answer",
    "answers/hamiltonian": "liouville_runs poincare_orbits",
    "answers/relativity": "charged_motion_answer collision_answer doppler_answer "
                          "elastic_answer particle_answer rocket_answer worldline_answer",
    "answers/rigid": "rigid_answer top_answer",
}
MOVES = {}
for dom, names in DOMAINS.items():
    for n in names.split():
        old, _, new = n.partition(":")
        MOVES[old] = "%s/%s" % (dom, new or old)

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
PAT = re.compile(r"(?:(?<![\w.\-/])|(?<=include/))mech/(%s)\.h\b"
                 % "|".join(sorted(MOVES, key=len, reverse=True)))
TEXT = (".c", ".h", ".md", ".py", ".sh", ".txt", ".json", ".js", ".mjs", ".cmake", ".yml",
        ".yaml", ".toml", ".in", ".html", ".css")


def rewrite(path):
    with open(path, encoding="utf-8") as fh:
        text = fh.read()
    new = PAT.sub(lambda m: "mech/%s.h" % MOVES[m.group(1)], text)
    if new != text:
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(new)
        return 1
    return 0


def tracked():
    out = subprocess.run(["git", "-C", ROOT, "ls-files"], capture_output=True, text=True,
                         check=True).stdout.split("\n")
    for f in out:
        base = os.path.basename(f)
        data = f.startswith("api/ops/") and f.endswith(".json")
        if f and not data and (f.endswith(TEXT) or base in ("CMakeLists.txt", "Makefile",
                                                             "Dockerfile")):
            yield os.path.join(ROOT, f)


def git_mv():
    for old, new in sorted(MOVES.items()):
        src = os.path.join(ROOT, "core/include/mech", old + ".h")
        dst = os.path.join(ROOT, "core/include/mech", new + ".h")
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        subprocess.run(["git", "-C", ROOT, "mv", src, dst], check=True)


if __name__ == "__main__":
    if sys.argv[1:] == ["--git-mv"]:
        git_mv()
    else:
        files = sys.argv[1:] or list(tracked())
        n = sum(rewrite(f) for f in files if os.path.isfile(f))
        print("%d files rewritten" % n)
