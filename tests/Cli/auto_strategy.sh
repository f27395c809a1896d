#!/usr/bin/env bash
# Usage: auto_strategy.sh APP
# --strategy auto as a user runs it: the pilot's choice is logged and recorded in --stats (strategy_choice), the
# render uses it, a flag given is never varied, the choice is kept for the next render of the same settings (any
# seed: no pilot, the same image for the same seed; --strategy-cache off pilots again), auto is the default,
# --strategy takes only scene and auto, and --compare --strategy auto (given, not the default) adds a row "auto" whose JSON holds the pilot's record (a ladder's and an
# equal-time comparison's).
set -eu
app=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The estimator and light sampler fixed by flags: the pilot varies the light selection alone (three pipelines on
# a GPU: lavapipe compiles each for seconds).
pilot=(--headless --quiet --scene cornell-box-lights --width 24 --spp 4096 --depth 6 --strategy auto
    --pilot-budget 1 --pilot-max-seconds 120 --estimator nee --light-sampler solid-angle --sampling random)
# A choice is kept only when its pilot measured every candidate within its budget (StrategyCache::store), and a
# machine loaded by other work can stretch a pilot past it: the first run is tried again, three times at most.
for attempt in 1 2 3; do
    rm -rf "$work/cache"
    "$app" "${pilot[@]}" --strategy-cache "$work/cache" --stats "$work/a.json" >/dev/null
    spent=0
    /usr/bin/python3 -c 'import json, sys; sys.exit(3 if json.load(open(sys.argv[1]))["strategy_choice"]["budget_spent"] else 0)' \
        "$work/a.json" || spent=$?
    [ "$spent" = 0 ] && break
    [ "$spent" != 3 ] && { echo "no strategy_choice.budget_spent in the pilot's stats"; exit 1; }
    [ "$attempt" = 3 ] && { echo "the pilot spent its budget in three runs: too loaded a machine to test the kept choice"; exit 1; }
done
/usr/bin/python3 - "$work/a.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
c = d["strategy_choice"]
rows = c["candidates"]
# Every candidate measured unless the pilot's wall time ran out first (a GPU compiles each one's pipeline).
assert len(rows) == 3 and (c["budget_spent"] or all(r["measurements"] > 0 for r in rows)), c
for r in rows:
    words = r["strategy"].split()
    assert words[:2] == ["nee", "solid-angle"] and words[3] == "random", f"a flag was varied: {r['strategy']}"
    assert r["measurements"] == 0 or (r["ms"] > 0 and r["relmse"] > 0), r
assert [r["differs_from_own"] for r in rows] == ["", "light-selection", "light-selection"], rows
assert c["chosen"].split()[2] == d["settings"]["light_selection"], (c["chosen"], d["settings"])
assert d["settings"]["estimator"] == "nee"
assert c["budget_seconds"] > 0 and c["pilot_width"] > 0
assert "cached" not in c, c
PY
# The same settings again, at another seed twice: the kept choice, no pilot, one image.
for run in 1 2; do
    "$app" "${pilot[@]}" --strategy-cache "$work/cache" --seed 5 --hdr "$work/kept$run.pfm" --stats "$work/kept$run.json" \
        >/dev/null
done
cmp -s "$work/kept1.pfm" "$work/kept2.pfm" || { echo "the kept choice rendered two images for one seed"; exit 1; }
"$app" "${pilot[@]}" --strategy-cache off --stats "$work/off.json" >/dev/null
/usr/bin/python3 - "$work/a.json" "$work/kept1.json" "$work/off.json" <<'PY'
import json, sys
first, kept, off = (json.load(open(f)) for f in sys.argv[1:])
assert kept["strategy_choice"]["cached"].endswith(".json"), kept["strategy_choice"]
assert kept["strategy_choice"]["chosen"] == first["strategy_choice"]["chosen"], (kept, first)
assert kept["settings"]["light_selection"] == first["settings"]["light_selection"]
assert kept["settings"]["seed"] == 5
assert "cached" not in off["strategy_choice"], "--strategy-cache off read the cache"
PY
# The default is auto: a render too short for a pilot records that it kept the scene's own; --strategy scene records
# no choice.
"$app" --headless --quiet --scene cornell-box-lights --width 8 --spp 1 --depth 2 --strategy-cache off \
    --stats "$work/default.json" >/dev/null
/usr/bin/python3 - "$work/default.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
c = d["strategy_choice"]
assert c["too_short"] and c["chosen"].split()[:3] == ["nee-mis", "projected", "bvh"], c
PY
# By default as when given: an estimator the pilot does not choose among stays, a scene file's nee (the pilot varies
# the light selection alone here, the sampler a flag) and restir-di (no pilot: its pixels are correlated).
"$app" --scene cornell-box-lights --export-scene "$work/nee.json" >/dev/null
/usr/bin/python3 - "$work/nee.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["render"]["estimator"] = "nee"
json.dump(d, open(sys.argv[1], "w"))
PY
# (The CPU's pilot only: which estimator stays is the app's, not the engine's; a GPU compiles a pipeline a candidate.)
nee=()
if [ "$2" != gpu ]; then
    "$app" --headless --quiet --scene "$work/nee.json" --width 24 --spp 4096 --depth 6 --pilot-budget 1 \
        --pilot-max-seconds 120 --light-sampler solid-angle --sampling random --strategy-cache off \
        --stats "$work/nee-stats.json" >/dev/null
    nee=("$work/nee-stats.json")
fi
"$app" --headless --quiet --scene cornell-box-lights --width 8 --spp 2 --depth 2 --estimator restir-di \
    --stats "$work/restir.json" >/dev/null
/usr/bin/python3 - "$work/restir.json" "${nee[@]}" <<'PY'
import json, sys
restir = json.load(open(sys.argv[1]))
assert "strategy_choice" not in restir and restir["settings"]["estimator"] == "restir-di", restir["settings"]
for f in sys.argv[2:]:
    nee = json.load(open(f))
    c = nee["strategy_choice"]
    assert not c["too_short"] and len(c["candidates"]) == 3, c
    assert all(r["strategy"].startswith("nee solid-angle") for r in c["candidates"]), c["candidates"]
    assert nee["settings"]["estimator"] == "nee", nee["settings"]
PY
"$app" --headless --quiet --scene cornell-box-lights --width 8 --spp 1 --depth 2 --strategy scene \
    --stats "$work/b.json" >/dev/null
grep -q strategy_choice "$work/b.json" && { echo "--strategy scene recorded a choice"; exit 1; }
"$app" --headless --quiet --scene cornell-box-lights --width 8 --spp 1 --strategy best >/dev/null 2>"$work/bad.txt" &&
    { echo "--strategy best was accepted"; exit 1; }
grep -q "strategy" "$work/bad.txt" || { cat "$work/bad.txt"; exit 1; }
# --compare: the auto row over the list's candidates, its choice in the table's JSON.
# (All of the render's time for its pilot: a pilot of 5 % of so small a render is too short to measure.)
"$app" --compare --quiet --engines "$2" --scene cornell-box-lights --width 16 --depth 4 --spp-list 256 --pilot-budget 1 \
    --reference-spp 1024 --reference-cache off --rounds 1 --strategy auto --estimator nee-mis --light-sampler projected \
    --light-selection bvh --samplings sobol,random --table "$work/t.json" >"$work/compare.txt" 2>"$work/compare.err" ||
    { cat "$work/compare.err"; exit 1; }
grep -q "strategy auto" "$work/compare.txt" || { cat "$work/compare.txt"; exit 1; }
/usr/bin/python3 - "$work/t.json" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
engine = sys.argv[2]
strategies = [r["strategy"] for r in d["rows"]]
assert strategies.count("auto") == 1 and len(strategies) == 3, strategies
auto = next(r for r in d["rows"] if r["strategy"] == "auto")[engine]
choice = auto["strategy_choice"][0]
assert len(choice["candidates"]) == 2 and choice["chosen"].split()[3] in ("sobol", "random"), choice
assert choice["candidates"][0]["measurements"] > 0, choice
PY
# --compare --equal-time: the rows' figures and the auto row's pilots (one per seed) in --table's JSON.
"$app" --compare --quiet --engines "$2" --scene cornell-box-lights --width 16 --depth 4 --equal-time 300 --seeds 2 \
    --pilot-budget 1 --reference-spp 1024 --reference-cache off --rounds 1 --strategy auto --estimator nee-mis \
    --light-sampler projected --light-selection bvh --samplings sobol,random --images "$work/eqt" \
    --table "$work/e.json" >"$work/eqt.txt" 2>"$work/eqt.err" || { cat "$work/eqt.err"; exit 1; }
/usr/bin/python3 - "$work/e.json" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
engine = sys.argv[2]
assert d["scene"] == "cornell-box-lights" and d["equal_time_ms"] == 300 and d["seeds"] == 2, d
assert d["reference_spp"] == 1024 and d["devices"][engine], d
rows = d["rows"]
assert [r["strategy"] for r in rows].count("auto") == 1 and len(rows) == 3, rows
assert sum(r["best"] for r in rows) == 1, rows
for r in rows:
    assert r["engine"] == engine and r["spp"] > 0 and r["ms"] > 0, r
    # The row's relMSE is the mean of its seeds', inside its interval.
    seeds = r["relmse_seeds"]
    assert len(seeds) == 2 and abs(r["relmse"] - sum(seeds) / 2) <= 1e-9 * r["relmse"], r
    assert r["relmse_ci95"][0] <= r["relmse"] <= r["relmse_ci95"][1], r
    assert r["efficiency"] > 0 and ("efficiency_over_best" in r) != r["best"], r
auto = next(r for r in rows if r["strategy"] == "auto")
choices = auto["strategy_choice"]
assert len(choices) == 2 and all(len(c["candidates"]) == 2 for c in choices), choices
assert auto["label"].startswith("auto"), auto
assert all(c["chosen"].split()[3] in ("sobol", "random") for c in choices), choices
assert "strategy_choice" not in rows[0], rows[0]
PY
