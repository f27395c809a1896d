#!/usr/bin/env bash
# Commands timed side by side on one core, interleaved: round after round, each command once, so that a drift
# of the machine (several % within a minute on the CI kind) hits all of them alike. Prints every round's wall
# times, then each command's mean and the ratio of the first command's time to each other's, as the mean and
# standard deviation of the per-round ratios (issue 11's "measured side by side in one run").
#   tests/Bench/interleave.sh ROUNDS CMD_1 CMD_2 [CMD...]
# Each CMD is one string, run by bash on core 0 (taskset), its output discarded. CORE overrides the core list
# (CORE=0,1 for a two-core render).
# Example (docs/notebook/PERFORMANCE.md §1): the books' code against this build.
#   A="--headless --scene rtrol-cornell-glass --width 600 --spp 16 --depth 50 --sampling stratified --pdf on --engine single --quiet"
#   tests/Bench/interleave.sh 8 ./book_O3 "build/bin/ray-tracing-cpu $A"
set -eu
rounds=$1
shift
[ $# -ge 2 ] || { echo "usage: $0 ROUNDS CMD_1 CMD_2 [CMD...]" >&2; exit 2; }
core=${CORE:-0}
times=$(mktemp)
trap 'rm -f "$times"' EXIT
for ((round = 1; round <= rounds; ++round)); do
    line=""
    for cmd in "$@"; do
        start=$EPOCHREALTIME
        taskset -c "$core" bash -c "$cmd" >/dev/null 2>&1 || { echo "failed: $cmd" >&2; exit 1; }
        line="$line $start:$EPOCHREALTIME"
    done
    echo "$line" >>"$times"
    python3 -c 'import sys; print(" ".join(f"{float(b) - float(a):.3f}" for a, b in (x.split(":") for x in sys.argv[1:])))' $line
done
python3 - "$times" "$@" <<'EOF'
import statistics, sys
rows = [[float(b) - float(a) for a, b in (x.split(":") for x in line.split())] for line in open(sys.argv[1])]
cmds = sys.argv[2:]
for i, cmd in enumerate(cmds):
    column = [r[i] for r in rows]
    line = f"[{i + 1}] mean {statistics.mean(column):.3f} s"
    if i > 0:
        ratios = [r[0] / r[i] for r in rows]
        sd = statistics.stdev(ratios) if len(ratios) > 1 else 0.0
        line += f", [1] / [{i + 1}] = {statistics.mean(ratios):.3f} ± {sd:.3f}"
    print(f"{line}  ({cmd})")
print(f"(± is the standard deviation over {len(rows)} rounds)")
EOF
