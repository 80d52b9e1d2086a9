#!/usr/bin/env bash
# Pipeline memory under a backlog (issue 15, item 5): peak RSS of `trajeval-pipeline watch --drain`
# draining a backlog of 10^3 and of 10^5 seeded 3D folder bundles of 100-pose pairs (as the
# launcher runs it, default settings), and their ratio (target: within 1.2x). The bundles are
# generated once into DATA (10^5 bundles: about 2 GB, 500 000 inodes; check `df -h -i` first) and
# hard-linked into a fresh root for every run; delete DATA afterwards. Each timed run holds the
# shared bench lock and runs at nice 10.
#
#   bench/pipeline-backlog.sh [--runs 1] [--small 1000] [--large 100000] [--poses 100] [--workers N]
#       [--before-pipeline OTHER/bin/trajeval-pipeline]
#       [--data DIR (default ${TMPDIR:-/tmp}/trajeval-pipeline-bench)] [--lock FILE] [--no-build]
# Takes about 6 min on a quiet 2-core machine with --runs 1 (plus ~1 min to generate the bundles once).
set -euo pipefail
cd "$(dirname "$0")/.."
args=()
build=1
for a in "$@"; do
  if [ "$a" = "--no-build" ]; then build=0; else args+=("$a"); fi
done
if [ $build = 1 ]; then
  echo "building the launcher (gradle :pipeline:installDist)" >&2
  gradle -q --no-daemon :pipeline:installDist 2>&1 | grep -v '^openjdk\|^OpenJDK\|^Note:' >&2 || true
fi
echo "$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(java -version 2>&1 | head -1)"
exec python3 bench/python/pipeline_bench.py backlog --runs 1 --poses 100 \
  --pipeline pipeline/build/install/trajeval-pipeline/bin/trajeval-pipeline \
  --data "${TMPDIR:-/tmp}/trajeval-pipeline-bench" --lock "${TRAJEVAL_BENCH_LOCK:-/tmp/trajeval-bench.lock}" \
  ${args[@]+"${args[@]}"}
