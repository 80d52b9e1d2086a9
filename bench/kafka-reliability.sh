#!/usr/bin/env bash
# Issue 19's broker fault table, re-run: a real broker in its own JVM killed with SIGKILL and
# restarted under the service (README, "Reliability: the Kafka mode and its broker").
# Usage: bench/kafka-reliability.sh [RUNS [FAULT...]]   (about 15 min for 300 runs; runs under nice)
set -euo pipefail
cd "$(dirname "$0")/.."
args="${*:-300}"
exec nice -n 19 gradle --no-daemon --console=plain -q :pipeline:reliability -Pargs="$args"
