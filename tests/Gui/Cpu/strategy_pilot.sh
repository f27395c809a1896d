#!/usr/bin/env bash
# Usage: strategy_pilot.sh APP   (needs a display: CTest runs it under xvfb-run)
# The panel's "Choose strategy (pilot)" (action choose-strategy, --strategy auto's pilot): the panel shows the
# strategy the pilot chose and the image is its render; the user then overrides it like any setting. (Which one
# it chooses is the engine tests' CpuAutoStrategy and docs/RESULTS.md §9: a short render's pilot is a few ms.)
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

status=0
"$app" --no-gpu --window-size 1100x760 --scene rtrol-cornell-box --width 96 --spp 1024 --depth 8 \
    --actions "wait;choose-strategy;wait;save=$work/chosen.png" --frames 3 --screenshot "$work/pilot.png" \
    --state-json "$work/chosen.json" 2>"$work/app.err" || status=$?
check_run strategy_pilot "$status" "$work/app.err"
"$app" --no-gpu --window-size 1100x760 --scene rtrol-cornell-box --width 96 --spp 1024 --depth 8 \
    --actions "wait;choose-strategy;wait;estimator=mixture;wait" --frames 2 \
    --state-json "$work/overridden.json" 2>"$work/app2.err" || status=$?
check_run strategy_pilot_override "$status" "$work/app2.err"
# A given --strategy auto opens the window on the pilot's choice; a setting given as a flag is not varied, and the
# pilot takes --pilot-max-seconds.
"$app" --no-gpu --window-size 1100x760 --scene rtrol-cornell-box --width 96 --spp 1024 --depth 8 --strategy auto \
    --light-sampler solid-angle --pilot-max-seconds 0.5 \
    --actions "wait" --frames 2 --state-json "$work/launch.json" 2>"$work/app3.err" || status=$?
check_run strategy_pilot_launch "$status" "$work/app3.err"
python3 - "$work" <<'PY'
import json, sys
work = sys.argv[1]
state = json.load(open(f"{work}/chosen.json"))
choice = state["strategy_choice"]
assert choice is not None, "no pilot's choice in the window's state"
estimator, sampler, selection = choice["chosen"].split()[:3]
panel = state["panel"]
assert (panel["estimator"], panel["light_sampler"], panel["light_selection"]) == (estimator, sampler, selection), \
    (panel, choice["chosen"])
assert state["image_matches_panel"] and state["failed_renders"] == 0, state
assert len(choice["candidates"]) >= 2 and choice["candidates"][0]["strategy"].startswith("mixture"), choice
over = json.load(open(f"{work}/overridden.json"))
assert over["panel"]["estimator"] == "mixture" and over["image_matches_panel"], over["panel"]
assert over["strategy_choice"] is not None, "the override must keep the pilot's record"
launch = json.load(open(f"{work}/launch.json"))
assert launch["strategy_choice"] is not None and launch["image_matches_panel"], launch
rows = launch["strategy_choice"]["candidates"]
assert len(rows) >= 2 and all(r["strategy"].split()[1] == "solid-angle" or r["strategy"].startswith("mixture")
                              for r in rows), rows
assert launch["strategy_choice"]["budget_seconds"] <= 0.5, launch["strategy_choice"]["budget_seconds"]
PY
python3 "$here/window_checks.py" settled "$work/chosen.json"
keep_pngs "$work"
echo "strategy pilot ok"
