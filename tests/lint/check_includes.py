#!/usr/bin/env python3
"""check_includes.py SOURCE_DIR — the include graph stays a tree of layers:
no file includes a .c file, no header includes itself through
other headers (a cycle), and no source file in core/, api/ or server/ is
longer than MAX_LINES without a stated reason ("Why one file" in its opening
comment); core's public headers are grouped by domain: at most MAX_TOP files
at the top of core/include/mech/, each an umbrella mech/<domain>.h that
includes every header of its folder mech/<domain>/ and nothing else. A file being split in another change may stand in PENDING, with
why: it is reported, not failed, and reported again once it is short enough
to leave the list.

Quoted includes are resolved as the compiler does: beside the including
file first, then the include folders the build gives (core/include, core,
api, server, tests). Angle-bracket includes are the system's and skipped.
Python 3 standard library only; reads the tree, runs nothing."""
import os
import re
import sys

MAX_LINES = 800
MAX_TOP = 15
MECH = "core/include/mech"
FOLDERS = ("core", "api", "server", "tests", "bench")
INCLUDE_DIRS = ("core/include", "core", "api", "server", "tests")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
SIZED = ("core/", "api/", "server/")
PENDING = {
}


def sources(root):
    for top in FOLDERS:
        for d, subdirs, files in os.walk(os.path.join(root, top)):
            subdirs[:] = [s for s in subdirs if s not in ("node_modules", "cases", "regress")]
            for f in files:
                if f.endswith((".c", ".h")):
                    yield os.path.relpath(os.path.join(d, f), root)


def resolve(root, src, name):
    for base in [os.path.dirname(src)] + list(INCLUDE_DIRS):
        p = os.path.normpath(os.path.join(base, name))
        if os.path.isfile(os.path.join(root, p)):
            return p
    return None


def umbrella_problems(root):
    """The top of core/include/mech/: umbrellas only, each complete."""
    out = []
    top = os.path.join(root, MECH)
    files = sorted(f for f in os.listdir(top) if os.path.isfile(os.path.join(top, f)))
    if len(files) > MAX_TOP:
        out.append(f"{MECH}/ holds {len(files)} files at its top (at most {MAX_TOP})")
    for f in files:
        folder = os.path.join(top, f[:-2])
        if not f.endswith(".h") or not os.path.isdir(folder):
            out.append(f"{MECH}/{f}: not an umbrella (no folder {MECH}/{f[:-2]}/): "
                       "a header belongs in its domain's folder")
            continue
        want = set()
        for d, _, hs in os.walk(folder):
            want |= {os.path.relpath(os.path.join(d, h), top) for h in hs if h.endswith(".h")}
        with open(os.path.join(top, f), encoding="utf-8") as fh:
            have = {n[len("mech/"):] for n in INCLUDE.findall(fh.read())}
        for h in sorted(want - have):
            out.append(f"{MECH}/{f} does not include mech/{h}")
        for h in sorted(have - want):
            out.append(f"{MECH}/{f} includes mech/{h}, which is not in its folder")
    return out


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else "."
    problems = []
    graph = {}
    for src in sorted(sources(root)):
        with open(os.path.join(root, src), encoding="utf-8", errors="replace") as fh:
            text = fh.read()
        deps = []
        for name in INCLUDE.findall(text):
            if name.endswith(".c"):
                problems.append(f"{src} includes a .c file: \"{name}\"")
            target = resolve(root, src, name)
            if target:
                deps.append(target)
        graph[src] = deps
        if src.startswith(SIZED) and src.endswith(".c"):
            n = text.count("\n")
            opening = text[: text.find("*/") + 2] if text.lstrip().startswith("/*") else ""
            long_file = n > MAX_LINES and "why one file" not in opening.lower()
            if long_file and src in PENDING:
                print(f"note: {src}: {n} lines (over {MAX_LINES}), pending: {PENDING[src]}")
            elif long_file:
                problems.append(f"{src}: {n} lines (over {MAX_LINES}) and its opening comment "
                                "states no reason (\"Why one file ...\")")
            elif src in PENDING:
                print(f"note: {src} is {n} lines now: take it out of PENDING")
    problems += umbrella_problems(root)
    # cycles among headers (a .c is never included, so only headers can close one)
    state, stack = {}, []

    def visit(u):
        state[u] = 1
        stack.append(u)
        for v in graph.get(u, ()):
            if not v.endswith(".h"):
                continue
            if state.get(v) == 1:
                problems.append("include cycle: " + " -> ".join(stack[stack.index(v):] + [v]))
            elif v not in state:
                visit(v)
        stack.pop()
        state[u] = 2

    for h in sorted(g for g in graph if g.endswith(".h")):
        if h not in state:
            visit(h)
    for p in problems:
        print(p)
    n_files = len(graph)
    if problems:
        print(f"0 passed, 1 failed ({len(problems)} problems in {n_files} files)")
        return 1
    print(f"1 passed, 0 failed ({n_files} files, {sum(map(len, graph.values()))} includes)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
