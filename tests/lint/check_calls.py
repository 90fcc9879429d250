#!/usr/bin/env python3
"""check_calls.py BUILD_DIR SOURCE_DIR — no two source files of core/, api/ or server/
depend on each other in a loop through their code ("no include
cycles"; check_includes.py covers the headers, this the calls).

Read from the compiled objects of libmech, libmechapi and mechd
(BUILD_DIR/CMakeFiles/<target>.dir/**/*.c.o) with binutils: `nm` says which
file defines each global symbol and whether it is a function, `objdump -r`
which symbols each file's code refers to. File A depends on file B when A's
code (a .text section) refers to a symbol B defines (a call, a function's
address, a variable), or A's data refers to a variable of B. A table in A's
data that holds B's functions' addresses is no dependency of A on B: that
is how the route table (api/run/routes.c) reaches the handlers, and how a handler
that runs other operations (/v1/batch) calls back into the pipeline without a
loop. Every loop of dependencies is printed with the symbols that close it.

An object whose source file is no longer in SOURCE_DIR (a file moved or
removed since that build) is left out.

Python 3 standard library; exits 77 (CTest: skipped) when nm or objdump is
missing or nothing is built, 1 on a loop, 0 otherwise."""
import os
import re
import shutil
import subprocess
import sys

TARGETS = ("mech", "mechapi", "mechd")
RELOC_SECTION = re.compile(r"^RELOCATION RECORDS FOR \[(.+)\]:")
SYMBOL = re.compile(r"^([A-Za-z_][A-Za-z0-9_.$]*)")
FILE_HEADER = re.compile(r"^(.+):\s+file format ")


def objects(build, source):
    """{source path: object path} of the targets' objects whose source exists."""
    found = {}
    for t in TARGETS:
        top = os.path.join(build, "CMakeFiles", t + ".dir")
        for d, _, files in os.walk(top):
            for f in files:
                if f.endswith(".c.o"):
                    obj = os.path.join(d, f)
                    src = os.path.relpath(obj, top)[: -len(".o")]
                    if os.path.isfile(os.path.join(source, src)):
                        found[src] = obj
    return found


def run(*cmd):
    return subprocess.run(cmd, capture_output=True, text=True, check=True).stdout


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else "build"
    source = sys.argv[2] if len(sys.argv) > 2 else "."
    if not shutil.which("nm") or not shutil.which("objdump"):
        print("skipped: nm or objdump (binutils) missing")
        return 77
    objs = objects(build, source)
    if not objs:
        print(f"skipped: no objects under {build}/CMakeFiles")
        return 77
    src_of = {obj: src for src, obj in objs.items()}
    order = sorted(src_of)
    owner, is_func = {}, {}
    # One nm and one objdump for all objects: "OBJ:value type name" lines,
    # and a "OBJ:     file format ..." line before each object's relocations.
    for line in run("nm", "-A", "-g", "--defined-only", *order).splitlines():
        p = line.split()
        obj = p[0].rpartition(":")[0] if p else ""
        if obj in src_of and len(p) == 3:
            owner.setdefault(p[2], set()).add(src_of[obj])
            is_func[p[2]] = p[1] in "TtWi"
    graph = {src: {} for src in objs}
    src, section = None, ""
    for line in run("objdump", "-r", *order).splitlines():
        head = FILE_HEADER.match(line)
        if head and head.group(1) in src_of:
            src, section = src_of[head.group(1)], ""
            continue
        m = RELOC_SECTION.match(line)
        if m:
            section = m.group(1)
            continue
        p = line.split()
        if src is None or len(p) != 3 or not section:
            continue
        s = SYMBOL.match(p[2])
        if not s or s.group(1) not in owner:
            continue
        sym = s.group(1)
        if not section.startswith(".text") and is_func.get(sym):
            continue  # a table of another file's functions: no dependency
        for dst in owner[sym]:
            if dst != src:
                graph[src].setdefault(dst, set()).add(sym)
    # Tarjan's strongly connected components, iteratively.
    index, low, on, stack, comps, counter = {}, {}, set(), [], [], [0]
    for root in sorted(graph):
        if root in index:
            continue
        work = [(root, iter(sorted(graph[root])))]
        index[root] = low[root] = counter[0]
        counter[0] += 1
        stack.append(root)
        on.add(root)
        while work:
            v, it = work[-1]
            w = next(it, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = counter[0]
                    counter[0] += 1
                    stack.append(w)
                    on.add(w)
                    work.append((w, iter(sorted(graph[w]))))
                elif w in on:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    comps.append(sorted(comp))
    for comp in comps:
        print("dependency loop: " + ", ".join(comp))
        for a in comp:
            for b in comp:
                if b in graph[a]:
                    print(f"    {a} -> {b}: {', '.join(sorted(graph[a][b]))}")
    edges = sum(len(v) for v in graph.values())
    if comps:
        print(f"0 passed, 1 failed ({len(comps)} loops among {len(graph)} files)")
        return 1
    print(f"1 passed, 0 failed ({len(graph)} files, {edges} dependencies, no loop)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
