#!/bin/sh
# quiet.sh — run a build or a test step with its full output kept in a log
# file, printing only what a person needs: the step's name and log on start,
# and on success one closing summary; on failure the lines that say what
# failed (compiler errors, failed tests) and the log's path.
#   quiet.sh configure LOG  cmake -S . -B DIR ...  the configure step
#   quiet.sh build LOG  cmake --build DIR ...     a build step
#   quiet.sh test  LOG  ctest ...                 a CTest run (run in its dir)
# The CTest summary line ("100% tests passed, 0 tests failed out of N") and
# the "Total Test time" line are always printed: CI reads them.
# Exit status: the step's own.
set -u
kind=${1:?usage: quiet.sh build|test LOG COMMAND...}
log=${2:?usage: quiet.sh build|test LOG COMMAND...}
shift 2
mkdir -p "$(dirname "$log")"
status=0
"$@" >"$log" 2>&1 || status=$?
case $kind in
configure)
  if [ "$status" = 0 ]; then echo "configured (log: $log)"; else cat "$log"; echo "configure FAILED (log: $log)"; fi
  ;;
build)
  if [ "$status" = 0 ]; then
    echo "built: $(grep -c 'Built target' "$log") targets (log: $log)"
  else
    # compiler and linker diagnostics, then the last lines for context
    grep -E 'error|Error|undefined reference|warning:' "$log" | head -n 60
    echo "--- last lines of $log:"
    tail -n 20 "$log"
    echo "build FAILED (full log: $log)"
  fi
  ;;
test)
  # one line per failing test, then CTest's own summary
  grep -E '^ *[0-9]+/[0-9]+ Test +#[0-9]+: .*(\*\*\*|Failed|Timeout|Exception|Not Run)' "$log" || true
  grep -E 'tests passed|tests failed out of|Total Test time|No tests were found' "$log" || true
  if [ "$status" != 0 ]; then
    # each failing test's own output (its last 60 lines): where the log is
    # thrown away with its machine (a container build, CI), this is all there is
    awk '
      function flush() { if (n) { s = n > 60 ? n - 60 : 0; for (i = s + 1; i <= n; i++) print buf[i]; print "--- end of " name } n = 0 }
      /^ *[0-9]+\/[0-9]+ Test +#[0-9]+: / || /^ *Start +[0-9]+: / || /tests passed|tests failed out of/ {
        flush(); grab = 0
        if ($0 ~ /(\*\*\*|Failed|Timeout|Exception)/ && $0 ~ /Test +#/) { grab = 1; name = $0; print "--- output of " $0 }
        next
      }
      grab { buf[++n] = $0 }
      END { flush() }' "$log" | head -n 400
    sed -n '/The following tests FAILED:/,$p' "$log" | head -n 80
    echo "tests FAILED (full output of each failing test: $log)"
  else
    echo "(full log: $log)"
  fi
  ;;
*) echo "quiet.sh: unknown kind $kind" >&2; exit 2 ;;
esac
exit "$status"
