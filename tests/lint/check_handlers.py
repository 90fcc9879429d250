#!/usr/bin/env python3
"""check_handlers.py SOURCE_DIR — the path of an operation predicts its handler's file.

Every operation of the route table is a data file api/ops/<domain>/<name>.json
(scripts/ops_gen.py); its handler (the data file's "handler") must be defined
beside it, in api/ops/<domain>/<name>.c, and <name> must be what the path
says: the path after /v1/, without a leading "<domain>/", with "/" and "-"
written "_" (POST /v1/rigid/inertia -> api/ops/rigid/inertia.c, POST
/v1/relativity/kinematics/decay -> api/ops/relativity/kinematics_decay.c,
POST /v1/trajectory -> api/ops/frames/trajectory.c).

EXCEPTIONS names the few handlers that share one file named for their path
prefix, because they share an encoder that belongs to neither alone
(docs/layout.md says which and why). Fails, naming the data file, on a name the
path does not predict, a handler defined elsewhere or nowhere, and on an
exception that is no longer needed. Python 3 standard library; exit 0 or 1.
"""
import json
import os
import re
import sys

# handler -> the file (relative to api/ops/) that holds it instead
EXCEPTIONS = {
    # mode_json, the wave-mode encoder both answers use
    "api_op_continuum_string": "continuum/continuum.c",
    "api_op_continuum_rod": "continuum/continuum.c",
}


def predicted_name(path, domain):
    rest = path[len("/v1/"):] if path.startswith("/v1/") else path
    if rest.startswith(domain + "/"):
        rest = rest[len(domain) + 1:]
    return re.sub(r"[/-]", "_", rest)


def defines(c_path, handler):
    try:
        text = open(c_path, encoding="utf-8").read()
    except OSError:
        return False
    return re.search(r"^json_t\s*\*\s*%s\s*\(" % re.escape(handler), text, re.M) is not None


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "."
    ops = os.path.join(src, "api", "ops")
    bad, n = [], 0
    for domain in sorted(os.listdir(ops)):
        ddir = os.path.join(ops, domain)
        if not os.path.isdir(ddir) or domain.startswith("_"):
            continue
        for f in sorted(os.listdir(ddir)):
            if not f.endswith(".json"):
                continue
            rel = "api/ops/%s/%s" % (domain, f)
            doc = json.load(open(os.path.join(ddir, f), encoding="utf-8"))
            name, handler = f[:-len(".json")], doc.get("handler", "")
            n += 1
            want = predicted_name(doc.get("path", ""), domain)
            if name != want:
                bad.append("%s: %s %s predicts api/ops/%s/%s.json" % (rel, doc.get("method"),
                                                                     doc.get("path"), domain, want))
            home = EXCEPTIONS.get(handler, "%s/%s.c" % (domain, name))
            if not defines(os.path.join(ops, home), handler):
                bad.append("%s: %s is not defined in api/ops/%s (the handler lives beside its "
                           "data, named for its path)" % (rel, handler, home))
            elif handler in EXCEPTIONS and defines(os.path.join(ddir, name + ".c"), handler):
                bad.append("%s: %s is in api/ops/%s/%s.c now: drop its exception"
                           % (rel, handler, domain, name))
    for b in bad:
        print(b)
    print("%d operations, %d exceptions, %d problems" % (n, len(EXCEPTIONS), len(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
