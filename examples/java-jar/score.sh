#!/usr/bin/env bash
# An ETL step around the executable jar: scores every pair of a table with
#   java -jar trajeval-VERSION-all.jar eval REF EST --out OUT_DIR/NAME.json
# and acts on the exit code of each run.
#
#   TRAJEVAL_JAR=trajeval-0.1.0-all.jar examples/java-jar/score.sh PAIRS.csv OUT_DIR
#
# PAIRS.csv: a header "name,reference,estimate", then one pair per line (paths relative to the
# table's folder). JVM options go in JAVA_OPTS (e.g. JAVA_OPTS=-Xmx8g); `java` reads
# JDK_JAVA_OPTIONS as well.
# Exit: 0 every pair scored; 2 some pair refused as bad input (rejected.txt says which and why:
# fix or drop the data, do not retry); 1 an internal error of trajeval (stop the job and report it,
# with the stderr of that run).
set -uo pipefail
table=${1:?usage: score.sh PAIRS.csv OUT_DIR}
out=${2:?usage: score.sh PAIRS.csv OUT_DIR}
jar=${TRAJEVAL_JAR:?set TRAJEVAL_JAR to the path of trajeval-VERSION-all.jar}
base=$(cd "$(dirname "$table")" && pwd)
mkdir -p "$out"
: > "$out/rejected.txt"
status=0
line_no=0
while IFS=, read -r name ref est || [ -n "$name" ]; do
  line_no=$((line_no + 1))
  [ "$line_no" -eq 1 ] && continue            # header
  [ -z "$name" ] && continue
  case "$ref" in /*) ;; *) ref="$base/$ref" ;; esac
  case "$est" in /*) ;; *) est="$base/$est" ;; esac
  # shellcheck disable=SC2086  # JAVA_OPTS holds several options
  java ${JAVA_OPTS:-} -jar "$jar" eval "$ref" "$est" --out "$out/$name.json" --json 2> "$out/$name.err"
  code=$?
  case $code in
    0) rm -f "$out/$name.err" ;;
    2) echo "$name: $(head -n 1 "$out/$name.err")" >> "$out/rejected.txt"; status=2 ;;
    *) echo "score.sh: $name: trajeval failed with exit $code (internal error):" >&2
       cat "$out/$name.err" >&2
       exit 1 ;;
  esac
done < "$table"
exit $status
