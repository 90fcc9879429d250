#!/bin/sh
# run.sh BUILD_DIR [SECONDS] — build the libFuzzer harnesses (tests/fuzz/) with
# clang into BUILD_DIR/fuzz, seed their corpora from tests/api/cases, replay
# the regression inputs (tests/fuzz/regress/<harness>/), and run each harness
# for SECONDS (default 60) with ASan+UBSan and leak detection:
#   fuzz_api     api_handle_ext() on every route (bytes as a request body)
#   fuzz_http    the request path behind libmicrohttpd without sockets
#   fuzz_server  the real server (server/*.c on libmicrohttpd, in-process) fed
#                raw bytes over TCP on 127.0.0.1
# Exits non-zero on any crash, leak, UB or failed check; the crashing input is
# kept as BUILD_DIR/fuzz/artifacts/<harness>/crash-* (reproduce with
# `BUILD_DIR/fuzz/<harness> FILE`; add it to tests/fuzz/regress/<harness>/).
# Installs clang + libclang-rt-14-dev when missing (install-deps.sh --fuzz).
set -eu
[ $# -ge 1 ] || { echo "usage: $0 BUILD_DIR [SECONDS]" >&2; exit 2; }
SRC=$(cd "$(dirname "$0")/../.." && pwd)
OUT=$(mkdir -p "$1/fuzz" && cd "$1/fuzz" && pwd)
SECS=${2:-60}
CC=${FUZZ_CC:-clang}
JOBS=${JOBS:-2}
"$SRC/scripts/install-deps.sh" --fuzz
command -v "$CC" >/dev/null || { echo "run.sh: $CC not found (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }

# The route table, generated from api/ops/<domain>/<operation>.json as the build does.
mkdir -p "$OUT/generated"
python3 "$SRC/scripts/ops_gen.py" "$SRC/api/ops" "$OUT/generated" --sources "$SRC/api" || exit 1

SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
CFLAGS="-std=c11 -O1 -g -D_POSIX_C_SOURCE=200809L -Wall -Wno-unused-parameter $SAN \
 -I$SRC/core/include -I$SRC/core -I$SRC/api -I$SRC/api/include -I$OUT/generated -I$SRC/server -I$SRC/tests/fuzz \
 -DMECHD_VERSION=\"0.1.0\" -DMECHD_BUILD_ID=\"fuzz\" -DMECHD_STATIC_DIR=\"$SRC/clients/web\" \
 $(pkg-config --cflags jansson gsl zlib libmicrohttpd)"
LIBS="$(pkg-config --libs jansson gsl zlib) -lm -lpthread"
export CFLAGS

# Objects of the program under test, instrumented for coverage (fuzzer-no-link).
# Rebuilt when the source or any project header is newer than the object.
mkdir -p "$OUT/obj"
# An object is named by its source path with / spelled @ (core@frames@earth.c.o),
# so the path can be read back from the name (core/ and api/ have folders).
newest_h=$(ls -t $(find "$SRC/core" "$SRC/api" -name '*.h') "$SRC"/server/*.h "$OUT"/generated/* 2>/dev/null | head -1)
{ find "$SRC/core" "$SRC/api" -name '*.c'; ls "$SRC"/server/*.c; } | grep -v "/server/main\.c$" |
  while read -r f; do
    o="$OUT/obj/$(echo "${f#$SRC/}" | tr / @).o"
    [ "$o" -nt "$f" ] && [ "$o" -nt "$newest_h" ] || echo "$f $o"
  done | xargs -r -n 2 -P "$JOBS" sh -c "$CC \$CFLAGS -fsanitize=fuzzer-no-link -c \"\$0\" -o \"\$1\""
# fuzz_api and fuzz_http: core, api and the static file cache; fuzz_server:
# every server file but main.c, on libmicrohttpd. (Objects of files that no
# longer exist are dropped.)
for o in "$OUT"/obj/*.o; do
  f=$SRC/$(basename "$o" .c.o | tr @ /).c
  [ -f "$f" ] || rm -f "$o"
done
OBJS=$(ls "$OUT"/obj/core@*.o "$OUT"/obj/api@*.o "$OUT"/obj/server@static.c.o)
SRV_OBJS="$OBJS $(ls "$OUT"/obj/server@*.o | grep -v -e '/server@main\.c\.o$' -e '/server@static\.c\.o$')"
HARNESSES="fuzz_api fuzz_http fuzz_server"
for h in fuzz_api fuzz_http; do
  # shellcheck disable=SC2086
  $CC $CFLAGS -fsanitize=fuzzer "$SRC/tests/fuzz/$h.c" $OBJS $LIBS -o "$OUT/$h"
done
# shellcheck disable=SC2086
$CC $CFLAGS -fsanitize=fuzzer "$SRC/tests/fuzz/fuzz_server.c" $SRV_OBJS \
  -Wl,--wrap=MHD_suspend_connection,--wrap=MHD_resume_connection \
  $(pkg-config --libs libmicrohttpd) $LIBS -o "$OUT/fuzz_server"

# Seed corpora (the live corpora grow in OUT/corpus/<harness> across runs).
FUZZ_LIST_ROUTES=1 "$OUT/fuzz_api" > "$OUT/routes.tsv"
/usr/bin/python3 "$SRC/tests/fuzz/build_corpus.py" "$OUT/routes.tsv" "$OUT/seeds"

status=0
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
report_failure() { # HARNESS LOG
  echo "!! $1 failed; log: $2; inputs:"; ls "$OUT/artifacts/$1"
  grep -m1 -A25 "ERROR\|fuzz:\|fuzz_server:\|runtime error\|deadly signal" "$2" || tail -30 "$2"
}
for h in $HARNESSES; do
  sub=${h#fuzz_}
  mkdir -p "$OUT/corpus/$h" "$OUT/artifacts/$h"
  # fuzz_server: the server's access log (a stderr line per request) is
  # discarded; libFuzzer and sanitizer output keep stderr.
  extra=""
  [ "$h" = fuzz_server ] && extra="-close_fd_mask=2"
  # Inputs that once failed must keep passing (each runs once).
  regress=$(ls "$SRC/tests/fuzz/regress/$h/"* 2>/dev/null || true)
  if [ -n "$regress" ]; then
    echo "== $h: $(echo "$regress" | wc -l) regression inputs"
    # shellcheck disable=SC2086
    if ! "$OUT/$h" $extra -detect_leaks=1 -timeout=20 -rss_limit_mb=2048 \
         -artifact_prefix="$OUT/artifacts/$h/" $regress > "$OUT/$h.regress.log" 2>&1; then
      status=1; report_failure "$h" "$OUT/$h.regress.log"; continue
    fi
  fi
  echo "== $h: $SECS s"
  # shellcheck disable=SC2086
  if ! "$OUT/$h" $extra -max_total_time="$SECS" -detect_leaks=1 -timeout=20 -rss_limit_mb=2048 \
       -max_len=8192 -print_final_stats=1 -artifact_prefix="$OUT/artifacts/$h/" \
       "$OUT/corpus/$h" "$OUT/seeds/$sub" > "$OUT/$h.log" 2>&1; then
    status=1; report_failure "$h" "$OUT/$h.log"
  else
    grep "cov:" "$OUT/$h.log" | tail -1
    awk '/stat::number_of_executed_units/ { n = $2 } /stat::average_exec_per_sec/ { r = $2 }
         /stat::peak_rss_mb/ { m = $2 } END { print n " executions, " r " exec/s, peak RSS " m " MB" }' "$OUT/$h.log"
  fi
done
exit $status
