#!/usr/bin/env bash
# The results store's figures (README "Fleet results" -> "Measured figures"): fills a SQLite store and
# a PostgreSQL 15 store (started by the test fixture on a free port, fsync off) with RUNS synthetic runs
# and times every row of the table: recording rate, whole-history trends (V4's trend_cells), a windowed
# trend, the gate v8 vs v9 (10^5 runs a side at 10^6) and its SQL, the gate on one robot; 7 repetitions
# each, wall min / median / max and (SQLite) the querying thread's CPU; load average before and after.
# Runs under nice -n 10, one database after the other.
#
#   bench/store-measure.sh [RUNS] [--sqlite-file FILE] [--only sqlite|postgresql]
#
# --sqlite-file FILE: keep the SQLite store there and reuse it (no fill) when it holds RUNS runs.
# On a quiet 2-core machine at 10^6: about 5 min for SQLite (4 min of it the fill), 8 min for PostgreSQL.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=1000000 file= only=
while [ $# -gt 0 ]; do
  case "$1" in
    --sqlite-file) file=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    [0-9]*) runs=$1; shift ;;
    *) echo "usage: bench/store-measure.sh [RUNS] [--sqlite-file FILE] [--only sqlite|postgresql]" >&2; exit 2 ;;
  esac
done
gradle --no-daemon --console=plain -q :core:jar :store:testClasses
for db in sqlite postgresql; do
  if [ -n "$only" ] && [ "$only" != "$db" ]; then continue; fi
  echo "== $db, $runs runs; uptime: $(uptime)"
  args="$runs $db"
  if [ "$db" = sqlite ] && [ -n "$file" ]; then args="$args $file"; fi
  start=$(date +%s)
  nice -n 10 gradle --no-daemon --console=plain -q :store:measure -Pargs="$args"
  echo "== $db took $(( $(date +%s) - start )) s"
done
