#!/bin/sh
# The physics library does not name the HTTP routes that serve it: the string
# "/v1/" (a route of the API) appears in core/ only in the answer-shaped layer,
# core/answers/ (one operation's computation each, from its request's parsed
# form to the figures its answer holds) and its headers core/include/mech/answers/.
# Physics code and its headers say what they compute, not which route asks.
# The layer sits above the physics: no physics file includes mech/answers/.
# Usage: check_core_routes.sh SOURCE_DIR
set -eu
src=$1
status=0
bad=$(cd "$src" && grep -rnF '/v1/' core | grep -vE '^core/(answers|include/mech/answers)/' || true)
if [ -n "$bad" ]; then
    echo "core/ outside core/answers/ names an API route (move the file to core/answers/<domain>/"
    echo "if it is one operation's computation, or say what it computes instead):"
    echo "$bad" | sed 's/^/    /'
    status=1
fi
up=$(cd "$src" && grep -rnE '#[[:space:]]*include[[:space:]]+"mech/answers[/.]' core |
     grep -vE '^core/(answers|include/mech/answers)/|^core/include/mech/answers\.h:' || true)
if [ -n "$up" ]; then
    echo "physics in core/ includes the answer layer above it:"
    echo "$up" | sed 's/^/    /'
    status=1
fi
[ $status = 0 ] && echo "1 passed, 0 failed" || echo "0 passed, 1 failed"
exit $status
