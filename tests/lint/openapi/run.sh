#!/bin/sh
# run.sh — lint mechd's OpenAPI document with Redocly CLI's recommended rules.
#   tests/lint/openapi/run.sh MECHD_BINARY
# Starts MECHD_BINARY on a free 127.0.0.1 port, fetches GET /v1/openapi.json
# and runs `redocly lint` (@redocly/cli, pinned in package-lock.json, installed
# with `npm ci` into ./openapi-lint under the current directory, the build
# tree) with redocly.yaml (extends: recommended). Any error fails; warnings
# are printed. Exits 77 (CTest: skipped) only when npm or node is missing here
# (CI has both). Redocly CLI needs Node.js >= 20.19: an older `node` (Debian 12
# ships 18) is replaced, as in tests/browser/run.sh, by the Node.js 20 build
# pinned in tests/browser/node-runtime, from the npm registry. Telemetry and
# the update check are off.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
mechd=${1:?usage: run.sh MECHD_BINARY}
case $mechd in /*) ;; *) mechd=$(pwd)/$mechd ;; esac
work=$(pwd)/openapi-lint
if ! command -v npm >/dev/null 2>&1 || ! command -v node >/dev/null 2>&1; then
  echo "SKIPPED: npm or node is missing on this machine (scripts/install-deps.sh installs them);" \
       "the OpenAPI lint runs where they are (CI)" >&2
  exit 77
fi
mkdir -p "$work"

# npm ci in DIR only when DIR's lock file changed since its last install
install_locked() {
  if ! cmp -s "$1/package-lock.json" "$1/node_modules/.mechd-lock" 2>/dev/null; then
    (cd "$1" && shift && npm ci --no-audit --no-fund --loglevel=error "$@")
    cp "$1/package-lock.json" "$1/node_modules/.mechd-lock"
  fi
}
node_ok() { # Redocly CLI's engines: >= 20.19 < 21, or >= 22.12
  node -e 'const [a,b]=process.versions.node.split(".").map(Number);
           process.exit((a===20&&b>=19)||a===21||(a===22&&b>=12)||a>22?0:1)' 2>/dev/null
}

if ! node_ok; then
  rt=$work/node-runtime
  echo "run.sh: node $(node --version) is older than Redocly CLI's minimum (20.19):" \
       "using the pinned Node.js from the npm registry in $rt" >&2
  mkdir -p "$rt"
  cp "$here/../../browser/node-runtime/package.json" "$here/../../browser/node-runtime/package-lock.json" "$rt/"
  install_locked "$rt" --ignore-scripts
  for d in "$rt"/node_modules/node-linux-*/bin; do
    if [ -x "$d/node" ]; then PATH=$d:$PATH; fi
  done
  export PATH
  # (npm skips an optional package whose download failed and still exits 0:
  # drop the install so the next run tries again)
  node_ok || { rm -rf "$rt/node_modules"; echo "run.sh: no Node.js >= 20.19 for $(uname -m) in $rt (did the npm registry answer?)" >&2; exit 1; }
  if [ -z "${NODE_EXTRA_CA_CERTS:-}" ] && [ -r /etc/ssl/certs/ca-certificates.crt ]; then
    NODE_EXTRA_CA_CERTS=/etc/ssl/certs/ca-certificates.crt
    export NODE_EXTRA_CA_CERTS
  fi
fi

cp "$here/package.json" "$here/package-lock.json" "$here/redocly.yaml" "$work/"
install_locked "$work"

# The document as the server serves it.
log=$work/mechd.log
"$mechd" --bind=127.0.0.1 --port=0 --token-file= >"$log" 2>&1 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT
port=
for _ in $(seq 1 100); do
  port=$(sed -n 's|^mechd listening on http://127\.0\.0\.1:\([0-9][0-9]*\).*|\1|p' "$log" | head -1)
  [ -n "$port" ] && break
  sleep 0.1
done
[ -n "$port" ] || { echo "run.sh: mechd did not start:" >&2; cat "$log" >&2; exit 1; }
python3 -c 'import sys, urllib.request
sys.stdout.buffer.write(urllib.request.urlopen(sys.argv[1], timeout=60).read())' \
  "http://127.0.0.1:$port/v1/openapi.json" >"$work/openapi.json"
kill "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
trap - EXIT

cd "$work"
REDOCLY_TELEMETRY=off REDOCLY_SUPPRESS_UPDATE_NOTICE=true NO_COLOR=1 \
  node node_modules/@redocly/cli/bin/cli.js lint --config redocly.yaml --format=stylish \
  --max-problems 1000 openapi.json
