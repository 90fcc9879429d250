#!/bin/sh
# run.sh BUILD_DIR [SECONDS] — build the libFuzzer harnesses (tests/fuzz/) with
# clang into BUILD_DIR/fuzz, seed their corpora from tests/api/cases, and run
# each for SECONDS (default 60) with ASan+UBSan and leak detection. Exits
# non-zero on any crash, leak, UB or failed check; the crashing input is kept
# as BUILD_DIR/fuzz/artifacts/<harness>/crash-* (reproduce with
# `BUILD_DIR/fuzz/<harness> FILE`). Needs clang + libclang-rt-dev (Debian).
set -eu
[ $# -ge 1 ] || { echo "usage: $0 BUILD_DIR [SECONDS]" >&2; exit 2; }
SRC=$(cd "$(dirname "$0")/../.." && pwd)
OUT=$(mkdir -p "$1/fuzz" && cd "$1/fuzz" && pwd)
SECS=${2:-60}
CC=${FUZZ_CC:-clang}
JOBS=${JOBS:-2}
command -v "$CC" >/dev/null || { echo "run.sh: $CC not found (apt-get install clang libclang-rt-14-dev)" >&2; exit 2; }

SAN="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
CFLAGS="-std=c11 -O1 -g -D_POSIX_C_SOURCE=200809L -Wall -Wno-unused-parameter $SAN \
 -I$SRC/core/include -I$SRC/core -I$SRC/api -I$SRC/server -I$SRC/tests/fuzz \
 -DMECHD_VERSION=\"0.1.0\" -DMECHD_BUILD_ID=\"fuzz\" -DMECHD_STATIC_DIR=\"$SRC/clients/web\" \
 $(pkg-config --cflags jansson gsl)"
LIBS="$(pkg-config --libs jansson gsl) -lm -lpthread"
export CFLAGS

# Objects of the program under test, instrumented for coverage (fuzzer-no-link).
mkdir -p "$OUT/obj"
ls "$SRC"/core/*.c "$SRC"/core/integrators/*.c "$SRC"/api/*.c "$SRC"/server/static.c |
  while read -r f; do
    o="$OUT/obj/$(echo "${f#$SRC/}" | tr / _).o"
    [ "$o" -nt "$f" ] || echo "$f $o"
  done | xargs -r -n 2 -P "$JOBS" sh -c "$CC \$CFLAGS -fsanitize=fuzzer-no-link -c \"\$0\" -o \"\$1\""
OBJS=$(ls "$OUT"/obj/*.o)
for h in fuzz_api fuzz_http; do
  # shellcheck disable=SC2086
  $CC $CFLAGS -fsanitize=fuzzer "$SRC/tests/fuzz/$h.c" $OBJS $LIBS -o "$OUT/$h"
done

# Seed corpora (the live corpora grow in OUT/corpus/<harness> across runs).
FUZZ_LIST_ROUTES=1 "$OUT/fuzz_api" > "$OUT/routes.tsv"
/usr/bin/python3 "$SRC/tests/fuzz/build_corpus.py" "$OUT/routes.tsv" "$OUT/seeds"

status=0
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for h in fuzz_api fuzz_http; do
  sub=${h#fuzz_}
  mkdir -p "$OUT/corpus/$h" "$OUT/artifacts/$h"
  echo "== $h: $SECS s"
  if ! "$OUT/$h" -max_total_time="$SECS" -detect_leaks=1 -timeout=20 -rss_limit_mb=2048 \
       -max_len=8192 -print_final_stats=1 -artifact_prefix="$OUT/artifacts/$h/" \
       "$OUT/corpus/$h" "$OUT/seeds/$sub" > "$OUT/$h.log" 2>&1; then
    status=1
    echo "!! $h failed; log: $OUT/$h.log; inputs:"; ls "$OUT/artifacts/$h"
    grep -m1 -A25 "ERROR\|fuzz:\|runtime error\|deadly signal" "$OUT/$h.log" || tail -30 "$OUT/$h.log"
  else
    grep "stat::number_of_executed_units\|stat::peak_rss_mb\|cov:" "$OUT/$h.log" | tail -3
  fi
done
exit $status
