#!/usr/bin/env bash
# The pipeline rows of the benchmark table (issue 15, item 2): runs/s of `trajeval-pipeline watch
# --drain` on 1000 seeded 10^4-pose 3D folder bundles (lesson preset, every guarantee on: fsync'd
# reports and ledger, atomic moves), and of `trajeval eval --batch` on the same 1000 pairs (one
# report per pair + summary.csv); wall, CPU (user + sys) per run, peak RSS, load average.
# The bundles are generated once (seeded, ~1.8 GB) into DATA and hard-linked into a fresh root for
# every run. Each timed run holds the shared bench lock and runs at nice 10.
#
#   bench/pipeline-throughput.sh [--runs 3] [--bundles 1000] [--poses 10000] [--workers N]
#       [--before-pipeline OTHER/bin/trajeval-pipeline --before-trajeval OTHER/bin/trajeval]
#       [--no-batch] [--data DIR (default ${TMPDIR:-/tmp}/trajeval-pipeline-bench)] [--lock FILE (default $TRAJEVAL_BENCH_LOCK or /tmp/trajeval-bench.lock)]
#       [--no-build]
# Takes about 3 min on a quiet 2-core machine with --runs 3 (plus ~30 s to generate the bundles once).
set -euo pipefail
cd "$(dirname "$0")/.."
args=()
build=1
for a in "$@"; do
  if [ "$a" = "--no-build" ]; then build=0; else args+=("$a"); fi
done
if [ $build = 1 ]; then
  echo "building the launchers (gradle :pipeline:installDist :cli:installDist)" >&2
  gradle -q --no-daemon :pipeline:installDist :cli:installDist 2>&1 | grep -v '^openjdk\|^OpenJDK\|^Note:' >&2 || true
fi
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(java -version 2>&1 | head -1)"
exec python3 bench/python/pipeline_bench.py throughput \
  --pipeline pipeline/build/install/trajeval-pipeline/bin/trajeval-pipeline \
  --trajeval cli/build/install/trajeval/bin/trajeval \
  --data "${TMPDIR:-/tmp}/trajeval-pipeline-bench" --lock "${TRAJEVAL_BENCH_LOCK:-/tmp/trajeval-bench.lock}" ${args[@]+"${args[@]}"}
