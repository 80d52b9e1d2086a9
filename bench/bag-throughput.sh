#!/usr/bin/env bash
# Pose messages per second read from a generated MCAP bag (BagBenchmarks, JMH): 10^6
# geometry_msgs/PoseStamped on /pose in chunks of 1000, and every 200 poses a 200 kB image and a
# 100 kB point cloud in chunks of their own (1.6 GB uncompressed); compression none and lz4,
# bag_crc all (data section CRC pass over the whole file) and chunks (only the chunks read).
# Runs at nice 10, one JMH fork, 2 warm-up and ITER measured reads per case; prints the best and
# the median read with the load average before and after (the machine may be shared).
#   bench/bag-throughput.sh [ITER]     (the bag is written once into bench/data/bags/, ~2.7 GB for both)
set -euo pipefail
cd "$(dirname "$0")/.."
ITER=${1:-7}
OUT=$(mktemp "${TMPDIR:-/tmp}/trajeval-bag-bench.XXXXXX.json")
trap 'rm -f "$OUT"' EXIT
before=$(cut -d' ' -f1-3 /proc/loadavg)
nice -n 10 gradle -q --no-daemon :bench:jmh \
  -Djmh.args="BagBenchmarks -f 1 -wi 2 -i $ITER -rf json -rff $OUT" > /dev/null
after=$(cut -d' ' -f1-3 /proc/loadavg)
echo "$(nproc) CPUs: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load average before: $before, after: $after"
python3 - "$OUT" <<'PY'
import json, statistics, sys
for r in json.load(open(sys.argv[1])):
    p = r["params"]
    ms = [x for fork in r["primaryMetric"]["rawData"] for x in fork]
    best, med = min(ms), statistics.median(ms)
    n = int(p["poses"])
    print(f'compression {p["compression"]:5} bag_crc {p["bagCrc"]:6}: best {best:7.1f} ms ({n / best / 1e3:5.2f} M poses/s), '
          f'median {med:7.1f} ms ({n / med / 1e3:5.2f} M poses/s), {len(ms)} reads')
PY
