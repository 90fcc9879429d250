#!/bin/sh
# Every symbol a library exports carries its layer's prefix (docs/design.md):
# libmech exports mech_*, libmechapi exports api_*. File-local functions must
# be static. Usage: check_symbols.sh LIBMECH.a LIBMECHAPI.a
set -eu
status=0
check() {
    lib=$1 prefix=$2
    bad=$(nm -g --defined-only "$lib" | awk 'NF == 3 && $2 ~ /[TDRB]/ {print $3}' | grep -v '^__' | grep -v "^$prefix" || true)
    if [ -n "$bad" ]; then
        echo "$lib exports symbols without the $prefix prefix:"; echo "$bad" | sed 's/^/    /'
        status=1
    fi
}
check "$1" mech_
check "$2" api_
[ $status = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
