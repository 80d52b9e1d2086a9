#!/usr/bin/env bash
# Where a trajeval run's memory comes from (issue 15, the memory system): runs the installed
# launcher once with JFR's allocation events on (settings=default,gc=high: every allocation made
# outside a thread-local allocation buffer or opening a new one, with its stack), then prints
# one markdown row per allocation site of objects of 64 KiB or more (the first org.trajeval frame
# and its caller), largest
# first, and the run's peak RSS and minor page faults (/usr/bin/time) beside the total.
# In ParallelGC's old generation every large array is a fresh bump-pointer allocation that the JVM
# zeroes, so each one costs a page fault per 4 KiB it spans: the total below, not only the peak,
# is what the kernel is paid for.
#
#   bench/alloc-sites.sh [--trajeval PATH] [--min-mib 1] [--keep FILE.jfr] -- eval REF EST [options...]
#
# Example: bench/alloc-sites.sh -- eval bench/data/planar_10000000_ref.csv bench/data/planar_10000000_est.csv \
#              --convention lesson --threads 1
# Not a timing (JFR's stacks slow the run a little); take the bench lock only if others are timing.
set -euo pipefail
cd "$(dirname "$0")/.."
TRAJEVAL=cli/build/install/trajeval/bin/trajeval
MIN_MIB=1
KEEP=
while [ $# -gt 0 ]; do
    case "$1" in
        --trajeval) TRAJEVAL=$2; shift 2 ;;
        --min-mib) MIN_MIB=$2; shift 2 ;;
        --keep) KEEP=$2; shift 2 ;;
        --) shift; break ;;
        *) echo "bench/alloc-sites.sh: unknown option $1 (the trajeval arguments follow --)" >&2; exit 2 ;;
    esac
done
[ $# -gt 0 ] || { echo "bench/alloc-sites.sh: give the trajeval arguments after --" >&2; exit 2; }
WORK=$(mktemp -d "${TMPDIR:-/tmp}/alloc-sites.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
JFR=${KEEP:-$WORK/run.jfr}
TRAJEVAL_OPTS="${TRAJEVAL_OPTS:-} -XX:StartFlightRecording:filename=$JFR,settings=default,gc=high" \
    /usr/bin/time -f '%M %R %e %U %S' -o "$WORK/time" "$TRAJEVAL" "$@" > "$WORK/out" 2> "$WORK/err" || {
    echo "bench/alloc-sites.sh: trajeval failed:" >&2; tail -5 "$WORK/err" >&2; exit 1; }
jfr print --json --events jdk.ObjectAllocationOutsideTLAB,jdk.ObjectAllocationInNewTLAB "$JFR" > "$WORK/events.json"
python3 bench/python/alloc_sites.py "$WORK/events.json" "$WORK/time" "$MIN_MIB"
