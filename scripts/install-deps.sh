#!/bin/sh
# Installs the Debian packages mechd needs to build, run and test, and only
# those that are missing: safe to run again and again (idempotent). Runs
# `apt-get update` only when something must be installed. Needs root (or sudo).
#   install-deps.sh          build, run and test (make run, make test)
#   install-deps.sh --bench  also the benchmarks' gnuplot-nox (the PNG plot),
#                            python3-scipy (the SciPy DOP853 baseline,
#                            imported by Debian's /usr/bin/python3) and wrk
#                            (bench_http, tests/load), gdb (tests/load prints
#                            mechd's thread stacks if a load round stalls),
#                            valgrind and strace (bench_http_instructions)
#   install-deps.sh --fuzz   also clang and libclang-rt-14-dev (libFuzzer and
#                            the sanitizers for tests/fuzz/run.sh, make fuzz)
# Options combine (install-deps.sh --bench --fuzz).
# Every form also installs what the browser test of the front end needs (make
# test runs it): Debian's chromium (/usr/bin/chromium; Playwright never
# downloads a browser), and node + npm only when no `node` / `npm` command
# exists (a machine may carry a newer Node.js from another package, which must
# not be replaced). playwright-core wants Node.js >= 20 and bookworm's nodejs
# is 18: then tests/browser/run.sh fetches a pinned Node.js 20 from the npm
# registry into the build tree (no system change).
set -eu

PKGS="build-essential cmake pkg-config libmicrohttpd-dev libjansson-dev libgsl-dev zlib1g-dev curl python3"
# python3-pip, python3-setuptools: the Python client's offline `pip install`; python3-venv:
# the built wheel installed into a fresh venv without setuptools (both in test_python_package.py)
PKGS="$PKGS python3-pip python3-setuptools python3-venv"
for opt in "$@"; do
  case "$opt" in
    --bench) PKGS="$PKGS gnuplot-nox python3-scipy wrk gdb valgrind strace" ;;
    --fuzz) PKGS="$PKGS clang libclang-rt-14-dev" ;;
    *) echo "usage: $0 [--bench] [--fuzz]" >&2; exit 2 ;;
  esac
done

command -v node >/dev/null 2>&1 || PKGS="$PKGS nodejs"
command -v npm >/dev/null 2>&1 || PKGS="$PKGS npm"
PKGS="$PKGS chromium"  # the browser test (tests/browser/run.sh)

missing=""
for p in $PKGS; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing="$missing $p"
  fi
done

if [ -z "$missing" ]; then
  exit 0
fi

echo "install-deps: installing:$missing" >&2
SUDO=""
if [ "$(id -u)" != 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
    echo "install-deps: need root to install:$missing" >&2; exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# shellcheck disable=SC2086
$SUDO apt-get install -y -qq --no-install-recommends $missing
