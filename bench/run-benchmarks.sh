#!/usr/bin/env bash
# Benchmarks trajeval against evo and the vectorised numpy version of the lesson's algorithm on
# the same seeded files, checks that their numbers agree, and writes the table into
# README.md (between the bench-table markers) and bench/results/bench.{md,json}.
#
#   bench/run-benchmarks.sh [--sizes 10000,100000,1000000,10000000] [--runs 3] [--runs-at 1000000=9]
#                           [--max-evo 1000000] [--max-check 100000] [--quiet-wait 10] [--no-readme]
#
# --max-evo N: largest pair evo is timed on (evo on 10^7 poses takes ~5 min and ~13 GiB per run).
# --max-check N: largest 3D pair on which trajeval's evo convention is checked against evo.
# --runs-at POSES=RUNS: runs for one size instead of --runs (repeatable; the noisy 10^6 row wants 9).
# --quiet-wait S: before each run of each tool, wait up to S s (default 10) for 0.5 s of idle machine.
# --recheck: only re-run the agreement checks on the outputs of the last run (no timing).
# Needs python3 with venv, /usr/bin/time, taskset; PyPI for the first run (evo, numpy, pandas).
set -euo pipefail
cd "$(dirname "$0")/.."
readme=(--readme README.md)
args=()
for a in "$@"; do
  if [ "$a" = "--no-readme" ]; then readme=(); else args+=("$a"); fi
done

if [ ! -x bench/.venv/bin/python ]; then
  echo "creating bench/.venv (evo, numpy, pandas from PyPI)" >&2
  python3 -m venv bench/.venv
  bench/.venv/bin/pip install -q -r bench/python/requirements.txt
fi
echo "building trajeval (gradle :cli:installDist)" >&2
gradle -q :cli:installDist 2>&1 | grep -v '^openjdk\|^OpenJDK' || true
export MPLBACKEND=Agg
exec bench/.venv/bin/python bench/python/run.py --trajeval cli/build/install/trajeval/bin/trajeval \
  --python bench/.venv/bin/python "${readme[@]}" "${args[@]}"
