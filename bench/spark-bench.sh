#!/usr/bin/env bash
# Spark's figures (README "On Spark"): trajeval-spark score in local[2] against trajeval eval --batch
# (--threads 2) in one JVM on the same pairs table; a standalone cluster with 2 workers against 1;
# and one big pair scored inside one task. Seeded 3D TUM files; every figure is the minimum over
# --runs, printed with the load average (uptime) before each run. Runs under nice -n 10.
#
#   bench/spark-bench.sh [--pairs 10000] [--poses 10000] [--files 20] [--runs 3]
#                        [--cluster] [--no-local] [--big 10000000] [--big-mem 6g] [--work DIR]
#
# --files F: distinct file pairs; the table's N rows cycle through them (each row is read and
#   scored in full; the files come from the page cache after the first read, for both sides).
# --no-local: skip the local[2] against eval --batch comparison.
# --cluster: also time the standalone cluster (Master + 1, then 2 Workers, 1 core and 2 GiB
#   each, on 127.0.0.1), submitting build/libs/trajeval-spark-*-all.jar through SparkSubmit.
# --big P: one P-pose pair in one task (local[1]) with --big-mem as the driver's heap (in local
#   mode the driver is the executor): wall time and peak RSS (/usr/bin/time).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
pairs=10000 poses=10000 files=20 runs=3 cluster=0 local=1 big=0 bigmem=6g work=
while [ $# -gt 0 ]; do
  case "$1" in
    --pairs) pairs=$2; shift 2 ;;
    --poses) poses=$2; shift 2 ;;
    --files) files=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --cluster) cluster=1; shift ;;
    --no-local) local=0; shift ;;
    --big) big=$2; shift 2 ;;
    --big-mem) bigmem=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
work=${work:-$(mktemp -d /tmp/trajeval-spark-bench.XXXXXX)}
mkdir -p "$work"
echo "building (gradle :cli:installDist :spark:installDist :spark:allJar)" >&2
gradle --no-daemon -q :cli:installDist :spark:installDist :spark:allJar 2>&1 | grep -v '^openjdk\|^OpenJDK' || true
trajeval=$root/cli/build/install/trajeval/bin/trajeval
tspark=$root/spark/build/install/trajeval-spark/bin/trajeval-spark
jar=$(ls "$root"/spark/build/libs/trajeval-spark-*-all.jar)
export SPARK_LOCAL_IP=127.0.0.1

# seeded 3D TUM pairs: a smooth path; the estimate is the path moved by a rigid motion plus noise
gen() { # N OUT_PREFIX SEED
  python3 - "$1" "$2" "$3" <<'PY'
import math, random, sys
n, prefix, seed = int(sys.argv[1]), sys.argv[2], int(sys.argv[3])
rnd = random.Random(seed)
with open(prefix + "-ref.txt", "w") as r, open(prefix + "-est.txt", "w") as e:
    for i in range(n):
        t = 1000.0 + 0.01 * i
        x, y, z = 5 * math.cos(0.001 * i), 5 * math.sin(0.0013 * i), 0.5 * math.sin(0.0007 * i)
        h = 0.5 * math.sin(0.0005 * i)
        qw, qz = math.cos(h / 2), math.sin(h / 2)
        r.write(f"{t:.4f} {x:.6f} {y:.6f} {z:.6f} 0 0 {qz:.9f} {qw:.9f}\n")
        e.write(f"{t + 0.002:.4f} {x + 1 + rnd.gauss(0, 0.02):.6f} {y - 2 + rnd.gauss(0, 0.02):.6f} "
                f"{z + rnd.gauss(0, 0.02):.6f} 0 0 {qz:.9f} {qw:.9f}\n")
PY
}
mkdir -p "$work/data"
for f in $(seq 1 "$files"); do
  [ -f "$work/data/p$f-est.txt" ] || gen "$poses" "$work/data/p$f" "$f"
done
table=$work/pairs.csv
echo "ref,est,run" > "$table"
for i in $(seq 0 $((pairs - 1))); do
  f=$((i % files + 1)); echo "$work/data/p$f-ref.txt,$work/data/p$f-est.txt,$i"
done >> "$table"

best() { sort -n | head -1; }
timed() { # LABEL COMMAND...: seconds of the fastest of $runs runs
  local label=$1; shift
  local times=()
  for r in $(seq 1 "$runs"); do
    rm -rf "$work/out"
    echo "$label run $r: load average $(uptime | sed 's/.*load average: //')" >&2
    local s=$(date +%s.%N)
    "$@" > "$work/last.log" 2>&1 || { cat "$work/last.log" >&2; exit 1; }
    times+=("$(echo "$(date +%s.%N) - $s" | bc)")
  done
  printf '%s\n' "${times[@]}" | best
}
echo
echo "$pairs pairs of $poses-pose 3D TUM files ($files distinct file pairs), min of $runs runs:"
if [ "$local" = 1 ]; then
batch=$(timed "eval --batch --threads 2" nice -n 10 "$trajeval" eval --batch "$table" --reports "$work/out" --threads 2)
local2=$(timed "trajeval-spark local[2]" nice -n 10 "$tspark" score --pairs "$table" --out "$work/out" --master 'local[2]')
printf '  eval --batch --threads 2 : %8.1f s  %8.1f pairs/s\n' "$batch" "$(echo "$pairs / $batch" | bc -l)"
printf '  trajeval-spark local[2]  : %8.1f s  %8.1f pairs/s  (%.2fx eval --batch)\n' "$local2" \
  "$(echo "$pairs / $local2" | bc -l)" "$(echo "$local2 / $batch" | bc -l)"
fi

if [ "$cluster" = 1 ]; then
  home=$work/spark-home
  rm -rf "$home"; mkdir -p "$home/jars"; : > "$home/RELEASE"
  # Spark's jars only: trajeval comes with the submitted jar
  for j in "$root"/spark/build/install/trajeval-spark/lib/*.jar; do
    case "$(basename "$j")" in spark-0*|core-0*) ;; *) ln -s "$j" "$home/jars/" ;; esac
  done
  opts=$(sed -n "s/^DEFAULT_JVM_OPTS='\(.*\)'$/\1/p" "$tspark" | tr -d '"')
  free_port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
  export SPARK_HOME=$home SPARK_SCALA_VERSION=2.13
  pids=()
  cleanup() { for p in "${pids[@]}"; do pkill -P "$p" 2>/dev/null || true; kill "$p" 2>/dev/null || true; done; }
  trap cleanup EXIT
  mport=$(free_port)
  java $opts -Xmx512m -cp "$home/jars/*" org.apache.spark.deploy.master.Master --host 127.0.0.1 \
    --port "$mport" --webui-port "$(free_port)" > "$work/master.log" 2>&1 & pids+=($!)
  submit() {
    nice -n 10 java $opts -Xmx1g -cp "$home/jars/*" org.apache.spark.deploy.SparkSubmit \
      --master "spark://127.0.0.1:$mport" --class org.trajeval.spark.SparkJob \
      --conf spark.driver.host=127.0.0.1 --conf spark.driver.bindAddress=127.0.0.1 --conf spark.ui.enabled=false \
      --conf spark.executor.memory=1500m --conf spark.executor.cores=1 \
      --conf spark.eventLog.enabled=true --conf spark.eventLog.dir="file://$work/events" "$jar" \
      score --pairs "$table" --out "$work/out" --partitions 16
  }
  # where the tasks of the newest run ran, from its event log: tasks and busy seconds per executor,
  # and the share of the job's task span during which two tasks ran at once
  where_tasks_ran() {
    python3 - "$(ls -t "$work"/events/* | head -1)" <<'PY'
import json, sys
tasks = []
for line in open(sys.argv[1]):
    e = json.loads(line)
    if e.get("Event") == "SparkListenerTaskEnd":
        i = e["Task Info"]
        tasks.append((i["Executor ID"], i["Launch Time"] / 1e3, i["Finish Time"] / 1e3))
if not tasks:
    sys.exit("no task in the event log")
per = {}
for ex, a, b in tasks:
    n, busy = per.get(ex, (0, 0.0)); per[ex] = (n + 1, busy + b - a)
start, end = min(t[1] for t in tasks), max(t[2] for t in tasks)
points = sorted([(a, 1) for _, a, _ in tasks] + [(b, -1) for _, _, b in tasks])
running, last, both = 0, start, 0.0
for t, d in points:
    if running >= 2: both += t - last
    running += d; last = t
print("    task span %.1f s; " % (end - start) + "; ".join(
    "executor %s: %d tasks, %.1f s busy" % (k, n, b) for k, (n, b) in sorted(per.items()))
    + "; two tasks at once %.0f %% of the span" % (100 * both / (end - start)))
PY
  }
  add_worker() {
    mkdir -p "$work/worker$1"
    java $opts -Xmx512m -cp "$home/jars/*" org.apache.spark.deploy.worker.Worker --host 127.0.0.1 \
      --port "$(free_port)" --webui-port "$(free_port)" --cores 1 --memory 2g --work-dir "$work/worker$1" \
      "spark://127.0.0.1:$mport" > "$work/worker$1.log" 2>&1 & pids+=($!)
    sleep 8
  }
  mkdir -p "$work/events"
  add_worker 1
  one=$(timed "cluster, 1 worker" submit)
  where_one=$(where_tasks_ran)
  add_worker 2
  two=$(timed "cluster, 2 workers" submit)
  where_two=$(where_tasks_ran)
  printf '  standalone, 1 worker     : %8.1f s  %8.1f pairs/s\n' "$one" "$(echo "$pairs / $one" | bc -l)"
  echo "$where_one"
  printf '  standalone, 2 workers    : %8.1f s  %8.1f pairs/s  (%.2fx one worker)\n' "$two" \
    "$(echo "$pairs / $two" | bc -l)" "$(echo "$one / $two" | bc -l)"
  echo "$where_two"
fi

if [ "$big" != 0 ]; then
  [ -f "$work/data/big-est.txt" ] || gen "$big" "$work/data/big" 99
  echo "ref,est" > "$work/big.csv"; echo "$work/data/big-ref.txt,$work/data/big-est.txt" >> "$work/big.csv"
  rm -rf "$work/out"
  echo "big pair: load average $(uptime | sed 's/.*load average: //')" >&2
  TRAJEVAL_SPARK_OPTS="-Xmx$bigmem" nice -n 10 /usr/bin/time -f '%e s wall, %M KiB peak RSS' \
    "$tspark" score --pairs "$work/big.csv" --out "$work/out" --master 'local[1]' 2> "$work/big.log" \
    || { cat "$work/big.log" >&2; exit 1; }
  printf '  one %d-pose pair, one task, heap %s: %s\n' "$big" "$bigmem" "$(tail -1 "$work/big.log")"
fi
echo "work folder: $work (delete when done)"
