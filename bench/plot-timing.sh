#!/usr/bin/env bash
# How long plotting a long pair takes: `trajeval eval` on a seeded planar pair of N poses (default
# 10^6), without figures, with --plot DIR (11 figures as SVG + PNG, index.html) and with
# --save-series DIR (gzip CSV), RUNS times each; prints the minimum and median wall time, the largest
# max RSS and the load average before and after each row (the machine may be shared).
#   bench/plot-timing.sh [N] [RUNS]        (after gradle :cli:installDist; runs itself under nice -n 10)
# The pair: reference at 100 Hz on x = 0.5 s + 40 sin(s/300), y = 30 cos(s/500) (m), heading as yaw;
# estimate 3 ms later, moved by a rigid offset (1.5 m, -2 m, 0.2 rad) plus a seeded wobble.
set -euo pipefail
cd "$(dirname "$0")/.."
N=${1:-1000000}
RUNS=${2:-3}
T=cli/build/install/trajeval/bin/trajeval
[ -x "$T" ] || { echo "build the launcher first: gradle :cli:installDist" >&2; exit 2; }
W=$(mktemp -d "${TMPDIR:-/tmp}/trajeval-plot-timing.XXXXXX")
trap 'rm -rf "$W"' EXIT
awk -v n="$N" 'BEGIN {
  srand(7); print "t,x,y,yaw" > "'"$W"'/ref.csv"; print "t,x,y,yaw" > "'"$W"'/est.csv";
  for (k = 0; k < n; k++) {
    s = 0.01 * k; x = 0.5 * s + 40 * sin(s / 300); y = 30 * cos(s / 500);
    yaw = atan2(-(30 / 500) * sin(s / 500), 0.5 + (40 / 300) * cos(s / 300));
    printf "%.2f,%.6f,%.6f,%.9f\n", 1000 + s, x, y, yaw > "'"$W"'/ref.csv";
    c = cos(0.2); d = sin(0.2); ex = c * x - d * y + 1.5 + 0.05 * (rand() - 0.5); ey = d * x + c * y - 2.0 + 0.05 * (rand() - 0.5);
    printf "%.6f,%.6f,%.6f,%.9f\n", 1000.003 + s, ex, ey, yaw + 0.2 > "'"$W"'/est.csv";
  } }'
run() { # label, extra args...
  local label=$1; shift
  local walls=() rss=0 load0
  load0=$(cut -d' ' -f1 /proc/loadavg)
  for i in $(seq "$RUNS"); do
    rm -rf "$W/out"
    nice -n 10 /usr/bin/time -f "%e %M" -o "$W/time" "$T" eval "$W/ref.csv" "$W/est.csv" --threads 2 "$@" > /dev/null
    read -r wall kb < "$W/time"
    walls+=("$wall"); [ "$kb" -gt "$rss" ] && rss=$kb
  done
  median=$(printf '%s\n' "${walls[@]}" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  min=$(printf '%s\n' "${walls[@]}" | sort -n | head -1)
  size=$( [ -d "$W/out" ] && du -sk "$W/out" | cut -f1 || echo 0)
  printf '%-28s min wall %6.2f s   median %6.2f s   max RSS %5d MiB   output %6d KiB   load %s -> %s\n' \
    "$label" "$min" "$median" $((rss / 1024)) "$size" "$load0" "$(cut -d' ' -f1 /proc/loadavg)"
}
echo "N = $N poses, $RUNS runs each, $(nproc) cores: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)"
run "eval (no figures)"
run "eval --plot DIR" --plot "$W/out"
run "eval --save-series DIR" --save-series "$W/out"
