#!/bin/sh
# Installs the Debian packages mechd needs to build, run and test, and only
# those that are missing: safe to run again and again (idempotent). Runs
# `apt-get update` only when something must be installed. Needs root (or sudo).
set -eu

PKGS="build-essential cmake pkg-config libmicrohttpd-dev libjansson-dev libgsl-dev curl python3"
# clang is only needed for the sanitizer build; gcc's sanitizers are used.

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
