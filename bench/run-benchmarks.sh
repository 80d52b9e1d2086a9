#!/usr/bin/env bash
# Benchmarks trajeval against evo and the vectorised numpy version of the lesson's algorithm on
# the same seeded files (planar CSV pairs and 3D TUM pairs), optionally the pipeline's drain and
# eval --batch, checks that their numbers agree, and writes one table with issue 15's targets
# judged under it into README.md (between the bench-table markers) and bench/results/bench.{md,json}.
# Run it under the shared bench lock as a whole: flock /tmp/trajeval-bench.lock bench/run-benchmarks.sh ...
#
#   bench/run-benchmarks.sh [--sizes 10000,100000,1000000,10000000] [--runs 3] [--runs-at 1000000=9]
#                           [--max-evo 1000000] [--evo-runs 1] [--max-check 100000] [--quiet-wait 10]
#                           [--pipeline 1000] [--pipeline-runs 3] [--backlog] [--no-readme]
#                           [--data bench/data] [--results bench/results]
#
# --max-evo N: largest pair evo is timed on (evo on 10^7 poses takes ~5 min and ~13 GiB per run).
# --evo-runs R: runs of each evo row (planar and 3D) per size (default 1; 3D evo takes 1-2 min at 10^6).
# --max-check N: largest 3D pair on which trajeval's evo convention is checked against evo.
# --runs-at POSES=RUNS: runs for one size instead of --runs (repeatable; the noisy 10^6 row wants 9).
# --quiet-wait S: before each run of each tool, wait up to S s (default 10) for 0.5 s of idle machine.
# --pipeline B: add the drain of B 10^4-pose 3D bundles and eval --batch of the same pairs (about
#   10 s each per run at 100 runs/s; B = 1000 is issue 15's item 2); --pipeline-runs R (default 3).
# --backlog: add the backlog rows, one drain of 10^3 and one of 10^5 100-pose bundles (about 5 min).
# --recheck: only re-run the agreement checks on the outputs of the last run (no timing).
# Duration with the defaults on a 2-core machine: about 13 min (10^6: 6 min, of which evo 1.5 min on
# the planar and 2 min on the 3D pair, once each; 10^7: 4-5 min); --pipeline 1000 adds about 1 min,
# --backlog about 5, --runs-at 1000000=9 about 2.5.
# Needs python3 with venv, /usr/bin/time, taskset; PyPI for the first run (evo, numpy, pandas).
set -euo pipefail
cd "$(dirname "$0")/.."
readme=(--readme README.md)
args=()
pipeline=()
for a in "$@"; do
  case "$a" in
    --no-readme) readme=() ;;
    --pipeline|--pipeline=*|--backlog) pipeline=(--trajeval-pipeline pipeline/build/install/trajeval-pipeline/bin/trajeval-pipeline)
                          args+=("$a") ;;
    *) args+=("$a") ;;
  esac
done

if [ ! -x bench/.venv/bin/python ]; then
  echo "creating bench/.venv (evo, numpy, pandas from PyPI)" >&2
  python3 -m venv bench/.venv
  bench/.venv/bin/pip install -q -r bench/python/requirements.txt
fi
if [ ${#pipeline[@]} -gt 0 ]; then
  echo "building trajeval and trajeval-pipeline (gradle :cli:installDist :pipeline:installDist)" >&2
  gradle -q :cli:installDist :pipeline:installDist 2>&1 | grep -v '^openjdk\|^OpenJDK\|^Note:' || true
else
  echo "building trajeval (gradle :cli:installDist)" >&2
  gradle -q :cli:installDist 2>&1 | grep -v '^openjdk\|^OpenJDK' || true
fi
export MPLBACKEND=Agg
exec bench/.venv/bin/python bench/python/run.py --trajeval cli/build/install/trajeval/bin/trajeval \
  --python bench/.venv/bin/python "${readme[@]}" ${pipeline[@]+"${pipeline[@]}"} "${args[@]}"
