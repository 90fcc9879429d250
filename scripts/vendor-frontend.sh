#!/bin/sh
# vendor-frontend.sh — (re)fetch the front end's third-party libraries from the
# npm registry at their pinned versions into clients/web/vendor/ and verify them.
#
#   scripts/vendor-frontend.sh          fetch, copy, verify against vendor/SHA256SUMS
#   scripts/vendor-frontend.sh --check  verify the committed files only (no network)
#
# The vendored files are committed: building, testing and serving the labs
# never need the network. This script is for a maintainer moving a pin (edit
# PINS below, run it with --update, review the diff) or checking that the
# committed copies are exactly what npm publishes. Each tarball is checked
# against the registry's sha512 integrity (npm pack does that), and each copied
# file against clients/web/vendor/SHA256SUMS.
#
#   scripts/vendor-frontend.sh --update  fetch and rewrite SHA256SUMS (a new pin)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
vendor=$root/clients/web/vendor

# package@version  files to copy from the package (relative to package/)
PINS='
three@0.185.0 build/three.module.min.js build/three.core.min.js LICENSE
d3@7.9.0 dist/d3.min.js LICENSE
'

mode=${1:-fetch}
check() { (cd "$vendor" && sha256sum --quiet -c SHA256SUMS) && echo "vendor-frontend: all files match SHA256SUMS"; }
if [ "$mode" = --check ]; then check; exit; fi

command -v npm >/dev/null 2>&1 || { echo "vendor-frontend: npm is missing" >&2; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
echo "$PINS" | while read -r spec files; do
  [ -n "$spec" ] || continue
  name=${spec%@*}; ver=${spec##*@}
  dest=$vendor/$name-$ver
  (cd "$tmp" && npm pack --silent "$spec" >/dev/null)   # verifies the registry's integrity hash
  mkdir -p "$tmp/$name" && tar xzf "$tmp/$name-$ver.tgz" -C "$tmp/$name"
  mkdir -p "$dest"
  for f in $files; do cp "$tmp/$name/package/$f" "$dest/$(basename "$f")"; done
  echo "vendor-frontend: $spec -> clients/web/vendor/$name-$ver/"
done
if [ "$mode" = --update ]; then
  (cd "$vendor" && find . -type f ! -name SHA256SUMS ! -name README.md | sort | xargs sha256sum > SHA256SUMS)
  echo "vendor-frontend: SHA256SUMS rewritten"
fi
check
