#!/bin/sh
# run_tsan.sh LOGDIR COMMAND [ARG...] — run one integration test against a
# ThreadSanitizer build of mechd (make test-tsan) and fail if TSan reported
# anything.
#
# mechd runs as a subprocess of the Python test, and a TSan report does not
# stop it (halt_on_error=0: every race of the run gets reported, not only the
# first), nor does its exit status always reach a check (tests kill servers,
# or ignore the status). So every TSan process writes its reports to
# LOGDIR/tsan.<pid> (log_path), which is emptied before the run; any such
# file afterwards fails the test, whatever the test itself said, and its
# contents are printed. exitcode=66 still makes a reporting mechd exit 66,
# which the tests that check a clean shutdown's status catch as well.
# A tsan.supp in tests/ (next to this directory), when there is one, holds
# the narrow suppressions for uninstrumented libraries, each with the reason
# it is not a race; none is committed today.
set -u
if [ $# -lt 2 ]; then
  echo "usage: $0 LOGDIR COMMAND [ARG...]" >&2
  exit 2
fi
logdir=$1
shift
here=$(cd "$(dirname "$0")" && pwd)
supp="$here/../tsan.supp"

mkdir -p "$logdir" || exit 2
rm -f "$logdir"/tsan.*

opts="log_path=$logdir/tsan halt_on_error=0 exitcode=66 second_deadlock_stack=1 history_size=7"
[ -f "$supp" ] && opts="$opts suppressions=$supp"
# A caller's TSAN_OPTIONS come last, so they can override these.
TSAN_OPTIONS="$opts ${TSAN_OPTIONS:-}"
export TSAN_OPTIONS

"$@"
rc=$?

reports=$(ls "$logdir"/tsan.* 2>/dev/null)
if [ -n "$reports" ]; then
  for f in $reports; do
    echo "==== ThreadSanitizer output: $f"
    cat "$f"
  done
  echo "FAIL ThreadSanitizer reported problems (see above; test exit status $rc)"
  exit 1
fi
if [ "$rc" -eq 0 ]; then
  echo "ok   no ThreadSanitizer reports"
fi
exit "$rc"
