#!/usr/bin/env bash
# Usage: refusals.sh APP   (needs a display: CTest runs it under xvfb-run)
# The window refuses what the command line refuses (issue 41): count=0 (at least 1, -1 for the scene's own) and
# a count whose scene would not fit in memory (it was accepted and grew past 2 GB), each named in a refusal, and the
# app's status non-zero for a script with a refused action.
set -u
app=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
"$app" --scene white-spheres --width 32 --spp 1 --actions "count=0;count=2000000000;count=50;frames=1" --frames 2 \
    >"$work/out.txt" 2>"$work/err.txt" || status=$?
[ "$status" -ne 0 ] || { cat "$work/err.txt"; echo "FAIL: refused actions, status 0"; exit 1; }
grep -q "action count=0 refused: count must be at least 1" "$work/err.txt" ||
    { cat "$work/err.txt"; echo "FAIL: count=0 not refused by name"; exit 1; }
grep -q "action count=2000000000 refused: count=2000000000 .*memory" "$work/err.txt" ||
    { cat "$work/err.txt"; echo "FAIL: a count that cannot fit not refused with its memory"; exit 1; }
echo "refusals ok"
