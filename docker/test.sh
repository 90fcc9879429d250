#!/bin/sh
# Proves the container set-up on this machine, where no registry is reachable:
#   1. makes the base image locally: debootstrap of Debian 12 (minbase) from
#      the mirror apt already uses, imported as debian:bookworm-slim
#      (cached in $MECHD_DOCKER_CACHE, default /var/cache/mechd-docker);
#   2. starts Debian's dockerd with its own data root, exec root and socket
#      (--storage-driver vfs), never touching a system engine;
#   3. builds the mechd image (docker/Dockerfile: its build stage runs
#      `make test`, the browser test included, with the host's extra CA
#      certificates for npm) and the nginx image, brings up docker/compose.yaml (nginx + three
#      replicas) on 127.0.0.1:$MECHD_HTTP_PORT (default 18080);
#   4. sends 600 requests through nginx (every operation's catalog example),
#      docker-kills one replica after 150 answers, and checks that every
#      request got its 200; checks the image runs as a non-root user and
#      that its HEALTHCHECK reports healthy;
#   5. tears everything down (compose stack, dockerd by its pid, data root,
#      docker0).
# Needs root. Installs debootstrap, docker.io, docker-compose with apt when
# missing. Takes 6-15 minutes (the image build installs chromium and runs
# the test suite on vfs).
# Exit status 0 on success, 1 on any failure.
set -eu

ROOT=$(cd "$(dirname "$0")/.." && pwd)
PORT=${MECHD_HTTP_PORT:-18080}
CACHE=${MECHD_DOCKER_CACHE:-/var/cache/mechd-docker}
WORK=$(mktemp -d /tmp/mechd-docker.XXXXXX)
PROJECT=mechdtest$$
T0=$(date +%s)
DOCKERD_PID=""

say() { echo "docker/test.sh [$(( $(date +%s) - T0 ))s] $*"; }
fail() { say "FAIL: $*"; exit 1; }

[ "$(id -u)" = 0 ] || { echo "docker/test.sh: needs root (dockerd, debootstrap)" >&2; exit 1; }

# ---- packages -----------------------------------------------------------------
missing=""
for p in debootstrap docker.io docker-compose curl iproute2; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing="$missing $p"
done
if [ -n "$missing" ]; then
  say "installing:$missing"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  # shellcheck disable=SC2086
  apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
# Debian's client, not whatever `docker` comes first on PATH.
DOCKER=/usr/bin/docker
COMPOSE=/usr/bin/docker-compose

cleanup() {
  rc=$?
  set +e
  if [ -n "$DOCKERD_PID" ]; then
    say "teardown"
    $COMPOSE -p "$PROJECT" -f "$WORK/ctx/docker/compose.yaml" down -v -t 5 >/dev/null 2>&1
    kill "$DOCKERD_PID" 2>/dev/null
    i=0; while kill -0 "$DOCKERD_PID" 2>/dev/null && [ $i -lt 30 ]; do sleep 1; i=$((i + 1)); done
    kill -9 "$DOCKERD_PID" 2>/dev/null
    # containerd-shims that outlived dockerd (only ours: they name our exec root)
    for p in $(pgrep -f "$WORK/exec" 2>/dev/null); do kill -9 "$p" 2>/dev/null; done
    ip link delete docker0 2>/dev/null
  fi
  umount "$WORK/exec" 2>/dev/null
  find "$WORK/data" -type d -name merged -exec umount {} \; 2>/dev/null
  rm -rf "$WORK"
  say "done, exit $rc"
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# ---- 1. base image ---------------------------------------------------------------
MIRROR=$(sed -n 's/^URIs:[[:space:]]*\([^[:space:]]*\).*/\1/p' /etc/apt/sources.list.d/*.sources 2>/dev/null \
         | grep -v security | head -1)
[ -n "$MIRROR" ] || MIRROR=$(awk '$1 == "deb" && $0 !~ /security/ { print $2; exit }' /etc/apt/sources.list 2>/dev/null)
[ -n "$MIRROR" ] || MIRROR=http://deb.debian.org/debian
mkdir -p "$CACHE"
BASE="$CACHE/bookworm-minbase.tar"
if [ ! -s "$BASE" ]; then
  say "debootstrap bookworm minbase from $MIRROR"
  debootstrap --variant=minbase bookworm "$WORK/rootfs" "$MIRROR" >"$WORK/debootstrap.log" 2>&1 \
    || { tail -20 "$WORK/debootstrap.log"; fail "debootstrap"; }
  rm -rf "$WORK/rootfs/var/cache/apt/archives/"*.deb "$WORK/rootfs/var/lib/apt/lists/"*
  tar -C "$WORK/rootfs" -cf "$BASE.tmp" . && mv "$BASE.tmp" "$BASE"
  rm -rf "$WORK/rootfs"
else
  say "base rootfs from cache $BASE"
fi

# ---- 2. our own dockerd ----------------------------------------------------------------
mkdir -p "$WORK/data" "$WORK/exec"
say "starting dockerd (vfs, $WORK)"
dockerd --data-root "$WORK/data" --exec-root "$WORK/exec" --pidfile "$WORK/dockerd.pid" \
        -H "unix://$WORK/docker.sock" --storage-driver vfs >"$WORK/dockerd.log" 2>&1 &
DOCKERD_PID=$!
export DOCKER_HOST="unix://$WORK/docker.sock"
i=0
until $DOCKER version >/dev/null 2>&1; do
  i=$((i + 1)); [ $i -lt 60 ] || { tail -20 "$WORK/dockerd.log"; fail "dockerd did not start"; }
  kill -0 "$DOCKERD_PID" 2>/dev/null || { tail -20 "$WORK/dockerd.log"; fail "dockerd exited"; }
  sleep 1
done
$DOCKER import - debian:bookworm-slim <"$BASE" >/dev/null
say "imported debian:bookworm-slim"

# ---- 3. images and the stack ---------------------------------------------------------------
# The legacy builder sends the whole context and ignores
# docker/Dockerfile.dockerignore: build from a copy without build trees.
mkdir -p "$WORK/ctx"
tar -C "$ROOT" --exclude='./build' --exclude='./build-*' --exclude='./.git' \
    --exclude='node_modules' --exclude='__pycache__' -cf - . | tar -C "$WORK/ctx" -xf -
# The build stage's npm ci must trust what this machine trusts (an HTTPS proxy's
# CA, say): hand it the host's extra CA certificates (build stage only).
for c in /usr/local/share/ca-certificates/*.crt; do
  if [ -f "$c" ]; then cp "$c" "$WORK/ctx/docker/ca-certificates/"; fi
done
say "building mechd image (runs the test suite)"
$DOCKER build -f "$WORK/ctx/docker/Dockerfile" -t mechd:latest "$WORK/ctx" >"$WORK/build.log" 2>&1 \
  || { tail -60 "$WORK/build.log"; fail "docker build mechd"; }
# What the build stage's `make test` said (the browser test's Node.js, the summary).
grep -E '^build stage:|browser/labs|tests passed|tests failed' "$WORK/build.log" | sed 's/^/  /'
say "building nginx image"
$DOCKER build -q -f "$WORK/ctx/docker/nginx.Dockerfile" -t mechd-nginx:latest "$WORK/ctx" >"$WORK/build-nginx.log" 2>&1 \
  || { tail -30 "$WORK/build-nginx.log"; fail "docker build nginx"; }
$DOCKER image ls --format '{{.Repository}}:{{.Tag}} {{.Size}}' | sed 's/^/  image /'

# The grader image: the build stage is cached, so this is one COPY (seconds).
$DOCKER build -q -f "$WORK/ctx/docker/Dockerfile" --target grader -t mechd-grader:latest "$WORK/ctx" \
  >"$WORK/build-grader.log" 2>&1 || { tail -30 "$WORK/build-grader.log"; fail "docker build grader"; }
guser=$($DOCKER image inspect -f '{{.Config.User}}' mechd-grader:latest)
case "$guser" in ""|root|0|0:*) fail "grader image runs as root ($guser)";; esac
gsize=$($DOCKER image inspect -f '{{.Size}}' mechd-grader:latest)
[ "$gsize" -lt 20000000 ] || fail "grader image is $gsize bytes (want one static binary)"
gout=$(echo '{"operation":"/v1/relativity/boost","request":{"vectors":[[1,0,0,0]],"velocity":{"beta":[0.6,0,0]}}}' \
  | $DOCKER run -i --rm --network none mechd-grader:latest)
echo "$gout" | grep -q '"gamma":1.25' || fail "grader image answered: $gout"
say "grader image: $gsize bytes, user $guser, no network: gamma 1.25 at beta 0.6"
$DOCKER image inspect -f '{{json .Config.Healthcheck.Test}}' mechd:latest | grep -q '"healthcheck"' \
  || fail "the mechd image's HEALTHCHECK is not mechd healthcheck"
$DOCKER run --rm --entrypoint sh mechd:latest -c 'command -v curl || command -v wget' >/dev/null 2>&1 \
  && fail "the mechd image still has curl or wget"

user=$($DOCKER image inspect -f '{{.Config.User}}' mechd:latest)
case "$user" in ""|root|0|0:*) fail "image runs as root ($user)";; esac
say "image user $user"

export MECHD_HTTP_PORT="$PORT"
$COMPOSE -p "$PROJECT" -f "$WORK/ctx/docker/compose.yaml" up -d --no-build >"$WORK/compose.log" 2>&1 \
  || { cat "$WORK/compose.log"; tail -20 "$WORK/dockerd.log"; fail "compose up"; }
URL="http://127.0.0.1:$PORT"
i=0
until curl -fsS -o /dev/null "$URL/healthz" 2>/dev/null; do
  i=$((i + 1)); [ $i -lt 60 ] || { $COMPOSE -p "$PROJECT" -f "$WORK/ctx/docker/compose.yaml" logs --tail 20; fail "stack not answering"; }
  sleep 1
done
say "stack up: $URL/healthz -> $(curl -fsS "$URL/healthz")"

# ---- 4. traffic, with one replica killed mid-run ------------------------------------------
victim=$($COMPOSE -p "$PROJECT" -f "$WORK/ctx/docker/compose.yaml" ps -q mechd2)
[ -n "$victim" ] || fail "no mechd2 container"
/usr/bin/python3 "$ROOT/docker/traffic.py" "$URL" 600 150 $DOCKER kill "$victim" || fail "requests failed"
# (restart: unless-stopped may already have brought it back: report, don't judge)
say "mechd2 killed mid-run (now $($DOCKER inspect -f '{{.State.Status}}, restarts {{.RestartCount}}' "$victim")); no request failed"

# HEALTHCHECK: a surviving replica must report healthy.
other=$($COMPOSE -p "$PROJECT" -f "$WORK/ctx/docker/compose.yaml" ps -q mechd1)
i=0
until [ "$($DOCKER inspect -f '{{.State.Health.Status}}' "$other")" = healthy ]; do
  i=$((i + 1)); [ $i -lt 30 ] || fail "mechd1 health: $($DOCKER inspect -f '{{json .State.Health}}' "$other")"
  sleep 1
done
say "mechd1 HEALTHCHECK healthy; running as uid $($DOCKER exec "$other" id -u)"
say "PASS"
