#!/usr/bin/env bash
# The 3D rows of the benchmark table (issue 15): 3D TUM pairs (nearest and interpolated
# association, se3/sim3, ATE + RPE) beside the planar CSV pair of the same size, and
# eval --batch on many 10^4-pose 3D pairs. Prints markdown rows: minimum of --runs runs under
# `nice -n 10`, wall and CPU (user + sys) time, peak RSS, B/pose above the 1000-pose baseline, and
# the load average before each run (the machine may be shared).
#
#   bench/speed-3d.sh [--sizes 1000000,10000000] [--runs 3] [--before OTHER/bin/trajeval]
#                     [--batch 1000] [--data bench/data] [--python python3-with-numpy]
#                     [--evo bench/.venv/bin] [--evo-runs 1]
set -euo pipefail
cd "$(dirname "$0")/.."
echo "building trajeval (gradle :cli:installDist)" >&2
gradle -q :cli:installDist 2>&1 | grep -v '^openjdk\|^OpenJDK\|^Note:' || true
echo "| poses | build | case | min wall (s) | min CPU (s) | CPU ns/pose | peak RSS (MiB) | B/pose above baseline | load average at each run |"
echo "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | --- |"
exec "${PYTHON:-python3}" bench/python/speed3d.py --trajeval cli/build/install/trajeval/bin/trajeval "$@"
