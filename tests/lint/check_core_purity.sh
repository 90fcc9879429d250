#!/bin/sh
# core/ is pure (docs/design.md, "Layers"): it never aborts, exits, asserts or does I/O, and
# holds no global mutable state. Checked on the source (calls) and on the
# built library (no writable data or bss symbols, static or not).
# Usage: check_core_purity.sh SOURCE_DIR LIBMECH.a
set -eu
src=$1 lib=$2
status=0
calls=$(grep -rnE '\b(abort|exit|_Exit|assert|printf|fprintf|puts|fopen|fwrite|perror)\s*\(' \
        "$src/core" --include='*.c' --include='*.h' | grep -vE '^\S+:\s*(\*|//)' || true)
if [ -n "$calls" ]; then
    echo "core/ calls abort/exit/assert or does I/O:"; echo "$calls" | sed 's/^/    /'
    status=1
fi
# Symbols in .data/.bss (tables of const pointers live in .data.rel.ro, which
# is read-only after relocation, and are fine).
data=$(objdump -t "$lib" | awk '$0 ~ /[ \t](\.data|\.bss)(\.[A-Za-z_0-9]+)?[ \t]/ && $0 !~ /\.data\.rel\.ro/ && $NF !~ /^\./ && $NF !~ /^__/ {print $NF}' || true)
if [ -n "$data" ]; then
    echo "libmech holds writable global data (mutable state):"; echo "$data" | sed 's/^/    /'
    status=1
fi
[ $status = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
