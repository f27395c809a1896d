#!/usr/bin/env bash
# Usage: plot.sh APP   (needs a display: CTest runs it under xvfb-run)
# The live convergence plot (issue 38): relMSE against render time on log-log axes, a line per engine x strategy of
# the panel's work, a point per render and per loop rendering's mean after 1, 2, 4, ... iterations, each measured
# against a reference of its own work at 4x its spp. Checked from --state-json and the screenshot, at 1280x800 and
# 1920x1080: one line per engine x strategy in the timings, labelled axes, each line's points in time order with
# a loop's means later and less noisy as samples accumulate, the timings' relMSE among the points, the lines'
# colours in the plot's pane, the panes apart; save-plot writes the figure and its points' CSV.
set -eu
app=$1
here=$(cd "$(dirname "$0")" && pwd)
. "$here/common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RT_REFERENCE_CACHE="$work/cache"
fail() { echo "FAIL: $*"; exit 1; }

actions="wait;spp=32;wait;estimator=mixture;spp=8;wait;spp=32;wait;loop=on;frames=30;loop=off;wait"
actions+=";wait-reference;save-plot=$work/plot.png"
for size in 1280x800 1920x1080; do
    status=0
    "$app" --no-gpu --window-size "$size" --scene cornell-box-lights --width 64 --spp 8 --seed 3 --estimator nee-mis \
        --engine multi --actions "$actions" --frames 2 --screenshot "$work/$size.png" --state-json "$work/$size.json" \
        2>"$work/$size.err" || status=$?
    check_run "$size" "$status" "$work/$size.err"
    python3 - "$work/$size.json" <<'PY'
import json, sys
state = json.load(open(sys.argv[1]))
drawn, lines = state["layout"]["plot_drawn"], state["plot"]
assert drawn["x_label"] == "render time (s)" and drawn["y_label"] == "relMSE", drawn
assert drawn["waiting"] == 0, drawn
strategies = {(t["engine"], t["estimator"]) for t in state["timings"] if t["rel_mse"] is not None}
assert len(strategies) == 2 and len(drawn["lines"]) == len(strategies), (strategies, drawn["lines"])
assert sorted(l["label"] for l in drawn["lines"]) == ["multi mixture", "multi nee-mis"], drawn["lines"]
lo, hi = drawn["x_range"]
for line in drawn["lines"]:
    times = [p[0] for p in line["points"]]
    assert times == sorted(times) and lo <= times[0] and times[-1] <= hi, line
# The timings' relMSE is a point's: the same render measured against the same reference (nee-mis: the loop's
# rows show its latest iteration, which is no point of its own).
for t in (t for t in state["timings"] if t["estimator"] == "nee-mis"):
    line = next(l for l in lines if l["estimator"] == t["estimator"])
    assert any(p["rel_mse"] == t["rel_mse"] and p["spp"] == t["spp"] for p in line["points"]), (t, line)
# The loop's means (mixture, 32 spp an iteration): 1, 2, 4, ... iterations, later and less noisy as they grow.
mixture = next(l for l in lines if l["estimator"] == "mixture")
means = [p for p in mixture["points"] if p["loop_mean"]]
assert len(means) >= 3, mixture
spp = [p["spp"] for p in means]
assert spp == [32 * 2 ** (i + 1) for i in range(len(means))], spp
assert all(a["seconds"] < b["seconds"] for a, b in zip(means, means[1:])), means
first = next(p for p in mixture["points"] if p["spp"] == 32)
assert means[-1]["rel_mse"] < first["rel_mse"] * 4 / (spp[-1] / 32), ("the mean does not converge", first, means[-1])
# The panes tile the window without overlap.
rects = {k: state["layout"][k] for k in ("panel", "timings", "plot")}
def apart(a, b):
    return a[0] + a[2] <= b[0] or b[0] + b[2] <= a[0] or a[1] + a[3] <= b[1] or b[1] + b[3] <= a[1]
names = list(rects)
for i in range(len(names)):
    for j in range(i + 1, len(names)):
        assert apart(rects[names[i]], rects[names[j]]), (names[i], names[j], rects)
image = state["layout"]["image"]
for name in ("timings", "plot"):
    assert apart(image, rects[name]), (name, image, rects[name])
print(f"plot ok: {len(drawn['lines'])} lines, {len(means)} loop means to {spp[-1]} spp")
PY
    # Each line's colour is drawn in the plot's pane.
    read -r x y w h < <(python3 -c "import json,sys; print(*json.load(open(sys.argv[1]))['layout']['plot'])" "$work/$size.json")
    for colour in $(python3 -c "import json,sys; print(*('rgb(%d,%d,%d)' % tuple(l['colour']) for l in json.load(open(sys.argv[1]))['layout']['plot_drawn']['lines']))" "$work/$size.json"); do
        count=$(convert "$work/$size.png" -crop "${w}x${h}+${x}+${y}" +repage -fuzz 6% -fill white -opaque "$colour" \
            -fill black +opaque white -format "%[fx:round(mean*w*h)]" info:)
        [ "$count" -ge 40 ] || fail "$size: the line of colour $colour has $count pixels in the plot"
    done
    file "$work/plot.png" | grep -q "PNG image data" || fail "save-plot wrote no figure"
    points=$(python3 -c "import json,sys; print(sum(len(l['points']) for l in json.load(open(sys.argv[1]))['plot']))" "$work/$size.json")
    [ "$(($(wc -l <"$work/plot.csv") - 1))" -eq "$points" ] || fail "the CSV holds $(wc -l <"$work/plot.csv") lines for $points points"
    rm "$work/plot.png" "$work/plot.csv"
done
keep_pngs "$work"
