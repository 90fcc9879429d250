#!/bin/sh
# One face per layer: the server (server/) sees the API layer only
# through api/include/api.h (the only API header on its include path) — no route table (api/run/routes.h), endpoint internals
# (api/run/endpoint.h) or other api/ header — and the API layer does not set up the
# process in a library init path (jansson's allocator and GSL's error handler
# are main()'s: api_install_json_allocator(), gsl_set_error_handler_off()).
# Usage: check_layers.sh SOURCE_DIR
set -eu
src=$1
status=0
api_headers=$(cd "$src/api" && find . -name '*.h' ! -path ./include/api.h | sed 's#^[.]/##' \
    | while read -r h; do echo "$h"; basename "$h"; done | sort -u | sed 's/[.]/[.]/g' | paste -sd'|' -)
bad=$(grep -nE "#include \"($api_headers)\"" "$src"/server/*.c "$src"/server/*.h \
        "$src"/server/standalone/*.c 2>/dev/null || true)
if [ -n "$bad" ]; then
    echo "server/ includes API headers other than api.h:"; echo "$bad" | sed 's/^/    /'
    status=1
fi
setup=$(grep -nE '\b(gsl_set_error_handler(_off)?|json_set_alloc_funcs)\s*\(' $(find "$src/api" -name '*.c') \
        $(find "$src/core" -name '*.c') | grep -v 'api/json/api_alloc.c:.*json_set_alloc_funcs(json_malloc_checked' || true)
if [ -n "$setup" ]; then
    echo "api/ or core/ sets process-wide state (main's job):"; echo "$setup" | sed 's/^/    /'
    status=1
fi
[ $status = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
