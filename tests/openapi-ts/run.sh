#!/bin/sh
# run.sh — typed clients of mechd's OpenAPI document compile a correct call.
#   tests/openapi-ts/run.sh MECHD_BINARY
# Starts mechd on a free port, fetches GET /v1/openapi.json, generates types with
# openapi-typescript (schema.d.ts) and @hey-api/openapi-ts (hey/), and runs tsc
# --strict on call_openapi_typescript.ts and call_hey_api.ts: a correct /v1/check
# and /v1/batch call (a nested operation's request is an open object, not
# Record<string, never>) must compile, the calls marked @ts-expect-error must not.
# The npm packages are pinned in package-lock.json and installed with `npm ci`
# into a work directory under the current directory (the build tree), never into
# the source tree; the npm registry is the only network access.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
mechd=${1:?usage: run.sh MECHD_BINARY}
case $mechd in /*) ;; *) mechd=$(pwd)/$mechd ;; esac
work=$(pwd)/openapi-ts-test
command -v npm >/dev/null 2>&1 || { echo "run.sh: npm is missing (scripts/install-deps.sh)" >&2; exit 1; }
mkdir -p "$work"
cp "$here/package.json" "$here/package-lock.json" "$here"/call_*.ts "$work/"
if ! cmp -s "$work/package-lock.json" "$work/node_modules/.mechd-lock" 2>/dev/null; then
  (cd "$work" && npm ci --no-audit --no-fund --loglevel=error --ignore-scripts)
  cp "$work/package-lock.json" "$work/node_modules/.mechd-lock"
fi
out=$work/mechd.out
"$mechd" --port 0 >"$out" 2>/dev/null &
pid=$!
trap 'kill $pid 2>/dev/null || true' EXIT
i=0
until grep -q "listening on" "$out" 2>/dev/null; do
  i=$((i + 1)); [ $i -lt 200 ] || { echo "run.sh: mechd did not start" >&2; exit 1; }
  sleep 0.1
done
url=$(sed -n 's/^mechd listening on \(http:[^ ]*\).*/\1/p' "$out")
curl -sS --fail-with-body "$url/v1/openapi.json" -o "$work/openapi.json"
kill $pid; trap - EXIT
cd "$work"
rm -rf hey schema.d.ts
./node_modules/.bin/openapi-typescript openapi.json -o schema.d.ts --silent
./node_modules/.bin/openapi-ts -i openapi.json -o hey -c @hey-api/client-fetch >/dev/null
if grep -nE "[^a-z_]request\??: Record<string, never>" schema.d.ts; then
  echo "run.sh: FAIL a request is typed Record<string, never>" >&2; exit 1
fi
./node_modules/.bin/tsc --noEmit --strict --skipLibCheck --target es2020 --module es2020 \
  --moduleResolution node call_openapi_typescript.ts call_hey_api.ts
echo "run.sh: openapi-typescript and @hey-api/openapi-ts types compile the /v1/check and /v1/batch calls"
