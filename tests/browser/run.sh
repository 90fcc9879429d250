#!/bin/sh
# run.sh — run the browser tests of the classroom front end.
#   tests/browser/run.sh MECHD_BINARY [SCREENSHOT_DIR]
# Installs playwright-core (pinned in package-lock.json) with `npm ci` into a
# work directory under the current directory (the build tree), never into the
# source tree, and never downloads a browser: Debian's /usr/bin/chromium is used
# (scripts/install-deps.sh installs it). Screenshots go to
# SCREENSHOT_DIR (default ./screenshots). Exits 0 when every check passes.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
mechd=${1:?usage: run.sh MECHD_BINARY [SCREENSHOT_DIR]}
case $mechd in /*) ;; *) mechd=$(pwd)/$mechd ;; esac
shots=${2:-$(pwd)/screenshots}
work=$(pwd)/browser-test
command -v node >/dev/null 2>&1 || { echo "run.sh: node is missing (scripts/install-deps.sh)" >&2; exit 1; }
[ -x "${CHROMIUM:-/usr/bin/chromium}" ] || { echo "run.sh: ${CHROMIUM:-/usr/bin/chromium} is missing (scripts/install-deps.sh)" >&2; exit 1; }
mkdir -p "$work"
cp "$here/package.json" "$here/package-lock.json" "$here/labs.test.mjs" "$work/"
# npm ci only when the lock file changed since the last install
if ! cmp -s "$here/package-lock.json" "$work/node_modules/.mechd-lock" 2>/dev/null; then
  (cd "$work" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
  cp "$here/package-lock.json" "$work/node_modules/.mechd-lock"
fi
export MECHD_WEB_ROOT="${MECHD_WEB_ROOT:-$here/../../clients/web}"
cd "$work" && exec node labs.test.mjs "$mechd" "$shots"
