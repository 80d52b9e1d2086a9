#!/usr/bin/env bash
# The start of a process that opens the results store, before/after (issue 15; README "Session 9: the SQLite
# driver's native library (i15s)"): CPU and wall of `trajeval db info` on a small store, of
# `trajeval-pipeline watch --root R --drain` on an empty root and on 10 bundles of 10^4-pose 3D TUM pairs,
# builds alternated run by run (A B B A ...), under the benchmark lock; then the files a build leaves in the
# temp folder after N normal starts and after N SIGKILLed ones.
#
#   bench/store-start.sh BEFORE_INSTALLS AFTER_INSTALLS [PAIRS (default 10)]
#     *_INSTALLS: a checkout whose cli/build/install/trajeval and pipeline/build/install/trajeval-pipeline exist
#   environment: TRAJEVAL_BENCH_LOCK (default /tmp/trajeval-bench.lock, held for each case's timed runs), TMPDIR (work folder's parent),
#     CASES (default "db-info drain-empty drain-10"), COUNTS (0: no temp-folder counts),
#     BUNDLES (default ${TMPDIR:-/tmp}/trajeval-pipeline-bench/bundles-1000x10000, from bench/pipeline-throughput.sh)
# Output: one line per run "case build wall_s user_s sys_s maxrss_kb", then the medians, then the temp-folder counts.
set -euo pipefail
before=$1 after=$2 pairs=${3:-10}
cases=${CASES:-db-info drain-empty drain-10}
lock=${TRAJEVAL_BENCH_LOCK:-/tmp/trajeval-bench.lock}
bundles=${BUNDLES:-${TMPDIR:-/tmp}/trajeval-pipeline-bench/bundles-1000x10000}
work=$(mktemp -d "${TMPDIR:-/tmp}/store-start.XXXXXX")
trap 'rm -rf "$work"' EXIT
cli() { echo "$1/cli/build/install/trajeval/bin/trajeval"; }
pipe() { echo "$1/pipeline/build/install/trajeval-pipeline/bin/trajeval-pipeline"; }
unset JAVA_OPTS TRAJEVAL_OPTS TRAJEVAL_PIPELINE_OPTS

# the small store each build lists, made once (schema created outside the timing)
for b in before after; do
    root=$work/$b; mkdir -p "$root"; dir=${!b}
    "$(cli "$dir")" db info --db "$root/small.db" >/dev/null
    mkdir -p "$root/empty"; "$(pipe "$dir")" watch --root "$root/empty" --drain >/dev/null 2>&1
done

ten_bundles() { # $1: a fresh root with 10 bundles in incoming/
    local i
    rm -rf "$1"; mkdir -p "$1/incoming"
    for i in 0 1 2 3 4 5 6 7 8 9; do
        cp -r "$bundles/run-00000$i" "$1/incoming/"; cp "$bundles/run-00000$i.done" "$1/incoming/"
    done
}

run() { # case build
    local c=$1 b=$2 dir=${!2} root=$work/$2 t
    case $c in
        db-info) cmd=("$(cli "$dir")" db info --db "$root/small.db") ;;
        drain-empty) cmd=("$(pipe "$dir")" watch --root "$root/empty" --drain) ;;
        drain-10) ten_bundles "$root/ten"; cmd=("$(pipe "$dir")" watch --root "$root/ten" --drain) ;;
    esac
    t=$(/usr/bin/time -f "%e %U %S %M" "${cmd[@]}" 2>&1 >/dev/null | tail -1)
    echo "$c $b $t"
}

# the lock is held for the timed runs only (a few minutes), not while copying bundles between cases
for c in $cases; do
    (
        flock 9
        echo "# $c: load before: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
        for ((i = 0; i < pairs; i++)); do
            if ((i % 2 == 0)); then run "$c" before; run "$c" after; else run "$c" after; run "$c" before; fi
        done
        echo "# $c: load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
    ) 9>"$lock"
done | tee "$work/runs.txt"
echo "# medians: case build wall user sys cpu(user+sys) maxrss_kb"
for c in $cases; do
    for b in before after; do
        awk -v c=$c -v b=$b '$1 == c && $2 == b { print $3, $4, $5, $4 + $5, $6 }' "$work/runs.txt" | python3 -c '
import sys, statistics as s
rows = [list(map(float, l.split())) for l in sys.stdin]
print(sys.argv[1], sys.argv[2], *["%.3f" % s.median(col) for col in zip(*rows[:])][:4], "%d" % s.median(r[4] for r in rows))' $c $b
    done
done

[ "${COUNTS:-1}" = 1 ] || exit 0
echo "# files left in the temp folder: case build count"
for b in before after; do
    dir=${!b} t=$work/tmp-$b-starts; mkdir -p "$t"
    for ((i = 0; i < 10; i++)); do
        JAVA_OPTS="-Djava.io.tmpdir=$t" "$(cli "$dir")" db info --db "$work/$b/small.db" >/dev/null
    done
    echo "10-normal-starts $b $(ls -A "$t" | wc -l)"
    t=$work/tmp-$b-kills; mkdir -p "$t"
    for ((i = 0; i < 10; i++)); do
        JAVA_OPTS="-Djava.io.tmpdir=$t" "$(pipe "$dir")" watch --root "$work/$b/empty" >/dev/null 2>&1 &
        pid=$! n0=$(ls -A "$t" | wc -l)
        # until the store is open: a new file in the temp folder (the driver's copy) or the store's WAL file
        for ((w = 0; w < 100; w++)); do
            sleep 0.1
            [ "$(ls -A "$t" | wc -l)" -gt "$n0" ] && break
            [ -f "$work/$b/empty/trajeval.db-wal" ] && sleep 1 && break
        done
        # the launcher execs java: $pid is the JVM
        kill -KILL "$pid"; wait "$pid" 2>/dev/null || true
    done
    echo "10-sigkills $b $(ls -A "$t" | wc -l)"
done
