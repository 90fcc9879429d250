#!/bin/sh
# readme-screenshots.sh — the README's pictures of the classroom front end
# (docs/img/*.png), taken from the real pages by tests/browser/screenshots.mjs:
# mechd serving this tree's clients/web, Debian's chromium headless through the
# browser test's pinned playwright-core (tests/browser/run.sh does the set-up).
#   scripts/readme-screenshots.sh [BUILD_DIR]   (default: build; mechd is built first)
# Run it after a change that shows in the pictures, and commit docs/img.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
[ -f "$build/CMakeCache.txt" ] || { echo "readme-screenshots.sh: $build is not configured (make all first)" >&2; exit 1; }
cmake --build "$build" --target mechd >/dev/null
cd "$build"
MECHD_BROWSER_SCRIPT=screenshots.mjs MECHD_WEB_ROOT="$root/clients/web" exec "$root/tests/browser/run.sh" "$build/mechd" "$root/docs/img"
