#!/bin/sh
# Runs the load scenarios against MECHD (default build/mechd):
#   sustained.py     60 s of mixed traffic at 64 connections (+10 s warm-up)
#   overload.py      3 waves of 40 long integrations against workers 2 + queue 4
#   slow_clients.py  500 idle/trickling connections, new clients, timeouts (45 s)
#   cheap_requests.py  one-vector boosts at 64 and 256 connections against
#                    --workers 2 --queue 4: every answer must be 200 (2 x 5 s)
#   fair_share.py    a long job under a flood of boosts ends inside a deadline of
#                    10 times its time alone (45 s)
# About 4 minutes in all; every scenario is bounded in time, talks only to
# 127.0.0.1, prints its figures and fails only on functional failures (error
# answers, lost answers, leaks, a dead server), never on timing.
# Needs wrk (apt-get install -y wrk) and Debian's /usr/bin/python3.
#   tests/load/run.sh [PATH/TO/mechd] [--quick]   (--quick: 10 s sustained run)
set -u
HERE=$(cd "$(dirname "$0")" && pwd)
MECHD=${1:-$HERE/../../build/mechd}
SECONDS_ARG=60
[ "${2:-}" = --quick ] && SECONDS_ARG=10
command -v wrk >/dev/null 2>&1 || { echo "tests/load: wrk not found (apt-get install -y wrk)" >&2; exit 1; }
rc=0
/usr/bin/python3 "$HERE/sustained.py" "$MECHD" --seconds "$SECONDS_ARG" || rc=1
/usr/bin/python3 "$HERE/overload.py" "$MECHD" || rc=1
/usr/bin/python3 "$HERE/slow_clients.py" "$MECHD" || rc=1
/usr/bin/python3 "$HERE/cheap_requests.py" "$MECHD" || rc=1
/usr/bin/python3 "$HERE/fair_share.py" "$MECHD" || rc=1
[ $rc = 0 ] && echo "tests/load: all scenarios passed" || echo "tests/load: FAILED"
exit $rc
