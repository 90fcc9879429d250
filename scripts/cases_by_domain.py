#!/usr/bin/env python3
"""cases_by_domain.py [--check] [REPO] — file each API case under its domain.

An API case is a folder holding request.json and expected.json
(tests/api/case_runner.c). Its domain is the folder of the operation its
request calls: the request's "path" (without a query string) is looked up
among the "path"s of api/ops/<domain>/<operation>.json, and the case goes to
tests/api/cases/<domain>/<case>/ (/v1/batch, /v1/check and /v1/examples are
in api/ops/tools/, so their cases go to tools/). A case whose path is no
operation (a 404, a problem document: HTTP behaviour alone) goes to http/.

Only cases still at the top level of tests/api/cases/ are moved (with
`git mv` when the tree is a git checkout and the case is tracked, else a
rename), so the script can run again at any time: after a merge that adds
cases at the top level, it files just those. A case already in a domain
folder is left where it is. It refuses, changing nothing, when a target
folder exists already or a top-level case has no readable request path.
--check moves nothing and exits 1 when a top-level case is left (for a lint).

Prints each move and then the number of cases per domain and in all.
Python 3 standard library only."""
import json
import os
import subprocess
import sys

HTTP = "http"  # cases that call no operation


def operation_domains(repo):
    """{operation path: domain folder} from api/ops/<domain>/*.json."""
    ops_dir = os.path.join(repo, "api", "ops")
    paths = {}
    for domain in sorted(os.listdir(ops_dir)):
        d = os.path.join(ops_dir, domain)
        if not os.path.isdir(d) or domain.startswith("_"):
            continue  # _defs/, _examples/: shared schema pieces and worked examples
        for f in sorted(os.listdir(d)):
            if not f.endswith(".json"):
                continue
            with open(os.path.join(d, f), encoding="utf-8") as fh:
                path = json.load(fh).get("path")
            if isinstance(path, str):
                paths[path] = domain
    return paths


def is_case(d):
    return os.path.isfile(os.path.join(d, "request.json"))


def case_domain(case_dir, paths):
    with open(os.path.join(case_dir, "request.json"), encoding="utf-8") as fh:
        path = json.load(fh).get("path")
    if not isinstance(path, str):
        raise ValueError(f"{case_dir}/request.json has no \"path\" string")
    return paths.get(path.split("?", 1)[0], HTTP)


def count(cases_dir):
    """{domain: number of cases} for the cases one folder down."""
    n = {}
    for domain in sorted(os.listdir(cases_dir)):
        d = os.path.join(cases_dir, domain)
        if os.path.isdir(d) and not is_case(d):
            n[domain] = sum(1 for c in os.listdir(d) if is_case(os.path.join(d, c)))
    return n


def tracked(repo, path):
    r = subprocess.run(["git", "-C", repo, "ls-files", "--error-unmatch", path],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return r.returncode == 0


def main(argv):
    check = "--check" in argv
    args = [a for a in argv if a != "--check"]
    repo = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), ".."))
    cases_dir = os.path.join(repo, "tests", "api", "cases")
    paths = operation_domains(repo)
    top = sorted(c for c in os.listdir(cases_dir) if is_case(os.path.join(cases_dir, c)))
    moves = []
    for c in top:
        try:
            domain = case_domain(os.path.join(cases_dir, c), paths)
        except (ValueError, OSError, json.JSONDecodeError) as e:
            print(f"cases_by_domain: {c}: {e}", file=sys.stderr)
            return 2
        if os.path.exists(os.path.join(cases_dir, domain, c)):
            print(f"cases_by_domain: {domain}/{c} exists already; {c} not moved", file=sys.stderr)
            return 2
        moves.append((c, domain))
    if check:
        for c, domain in moves:
            print(f"tests/api/cases/{c} belongs in tests/api/cases/{domain}/ "
                  "(run scripts/cases_by_domain.py)")
        return 1 if moves else 0
    git = os.path.isdir(os.path.join(repo, ".git")) or os.path.isfile(os.path.join(repo, ".git"))
    for c, domain in moves:
        src = os.path.join(cases_dir, c)
        dst_dir = os.path.join(cases_dir, domain)
        os.makedirs(dst_dir, exist_ok=True)
        dst = os.path.join(dst_dir, c)
        if git and tracked(repo, src):
            subprocess.run(["git", "-C", repo, "mv", src, dst], check=True)
        else:
            os.rename(src, dst)
        print(f"{c} -> {domain}/")
    n = count(cases_dir)
    print(" ".join(f"{d}: {k}" for d, k in n.items()))
    print(f"{sum(n.values())} cases in {len(n)} domain folders, {len(moves)} moved now")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
