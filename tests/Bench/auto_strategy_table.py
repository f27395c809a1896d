#!/usr/bin/env python3
"""Issue 37's table for --strategy auto from auto_strategy.sh's CSVs. Per scene, the efficiency 1/(relMSE s) of a
row is the inverse of its mean over seeds of relMSE x s (as --compare's equal-time table), each relMSE less its
reference's own (from the full comparison's CSV: every row is measured against that one reference file); the auto row (label
"auto: ..."; its time includes its pilot's). From the full comparison: the best strategy and auto; from the recheck
(fresh seeds, the same reference): the best again, the scene's own strategy and auto. The ratios use the recheck
where it exists. Standard library only.

    auto_strategy_table.py OUT_DIR          a Markdown table on stdout
    auto_strategy_table.py --best FILE.csv  the best strategy's words (estimator sampler selection sampling rr)
    auto_strategy_table.py --pilots OUT_DIR what each recheck's pilot saw (SCENE-auto-SEED.json, --table's) against
                                            the full comparison: per candidate, its time per path, error per path
                                            and efficiency over the scene's own's, by the pilot and by the
                                            comparison; the final round's challenger and the choice marked
    auto_strategy_table.py --leads OUT_DIR...  each pilot's final-round challenger: its lead over the own (the ratio
                                            of their final efficiencies), two standard errors of its log, the same
                                            without the own's worst pair, whether the switch would take it at 10 %
                                            and at 5 %, and the comparison's ratio of the two (the true lead)
"""
import csv
import math
import json
import statistics
import sys
from pathlib import Path


def reference_relmse(path):
    """The reference's own relMSE, from the full comparison's CSV (the rechecks use its reference file, whose own
    error their CSVs do not know): part of every row's relMSE against it, subtracted from each."""
    values = [float(r["reference_relmse"]) for r in csv.DictReader(path.open())]
    return max(values[0], 0.0) if values else 0.0


def costs(path, reference=0.0, wall=False):
    """{strategy or 'auto': [(relMSE - the reference's own) x s per seed]}, and the strategies auto chose. The time
    is the engine's clock where the row has one (a GPU's), else the wall clock; with `wall`, the wall clock always (a
    GPU's auto row then holds its pilot's host time too: compiling the candidates, the search's host side)."""
    rows = list(csv.DictReader(path.open()))
    cost, chosen = {}, []
    for r in rows:
        ms = float(r["gpu_ms"]) if float(r["gpu_ms"]) >= 0 and not wall else float(r["wall_ms"])
        key = "auto" if r["label"].startswith("auto") else r["strategy"]
        if key == "auto":
            chosen.append(r["strategy"])
        own = float(r["relmse"]) - reference
        if own <= 0.0:
            raise SystemExit(f"{path}: a relMSE {r['relmse']} at or below its reference's own {reference}: "
                             "the reference is too noisy for the rows (more --reference-spp)")
        cost.setdefault(key, []).append(own * ms * 1e-3)
    return cost, chosen


def efficiencies(path, reference=0.0, wall=False):
    """{strategy or 'auto': efficiency}, and the strategies auto chose (`wall`: as costs)."""
    cost, chosen = costs(path, reference, wall)
    return {k: 1.0 / statistics.mean(v) for k, v in cost.items()}, chosen


def ratio(numerator, denominator):
    """Efficiency ratio of two rows from their seeds' costs (the denominator's mean cost over the numerator's), with
    its 95 % interval by the delta method on the log of the ratio (independent seeds)."""
    def log_variance(c):
        return statistics.variance(c) / (len(c) * statistics.mean(c) ** 2) if len(c) > 1 else float("inf")
    value = statistics.mean(denominator) / statistics.mean(numerator)
    half = 1.96 * math.sqrt(log_variance(numerator) + log_variance(denominator))
    return value, value * math.exp(-half), value * math.exp(half)


def strategy_of(settings):
    rr = settings["russian_roulette"]  # a word, or true / false in files written before the sqrt rule
    rr = "rr-" + (("on" if rr else "off") if isinstance(rr, bool) else rr)
    return f'{settings["estimator"]} {settings["light_sampler"]} {settings["light_selection"]} {settings["sampling"]} {rr}'


def best_of(eff):
    grid = {k: v for k, v in eff.items() if k != "auto"}
    return max(grid, key=grid.get)


def scene_rows(out, wall=False):
    """One dict per scene of OUT_DIR: scene, strategies, best, best_full, best_again, own, own_eff, chosen, auto_eff
    (`wall`: every time on the wall clock, as costs)."""
    rows = []
    for path in sorted(Path(out).glob("*.csv")):
        if "recheck" in path.stem:
            continue
        scene = path.stem
        reference = reference_relmse(path)
        full, _ = efficiencies(path, reference, wall)
        best = best_of(full)
        own_name = strategy_of(json.load((Path(out) / f"{scene}-defaults.json").open())["settings"])
        recheck = Path(out) / f"{scene}-recheck.csv"
        again = Path(out) / f"{scene}-recheck-best.csv"
        if recheck.exists() and again.exists():
            r, chosen = costs(recheck, reference, wall)
            b, _ = costs(again, reference, wall)
            best_cost, own_cost, auto_cost = list(b.values())[0], r[own_name], r["auto"]
        else:
            f, chosen = costs(path, reference, wall)
            chosen = []
            best_cost, own_cost, auto_cost = f[best], f.get(own_name, [float("nan")]), f["auto"]
        rows.append({"scene": scene, "strategies": len(full) - 1, "best": best, "best_full": full[best],
                     "best_again": 1.0 / statistics.mean(best_cost), "own": own_name, "chosen": chosen,
                     "reference_share": reference,
                     "seeds": len(auto_cost), "own_best": ratio(own_cost, best_cost),
                     "auto_best": ratio(auto_cost, best_cost), "auto_own": ratio(auto_cost, own_cost)})
    return rows


def per_path(path, reference):
    """{strategy: (ms per spp, (relMSE - the reference's own) x spp, efficiency)} of the full comparison's CSV: the
    means over its seeds, the efficiency as the main table's (the inverse of the mean of relMSE x s)."""
    sums = {}
    for r in csv.DictReader(path.open()):
        if r["label"].startswith("auto"):
            continue
        ms = float(r["gpu_ms"]) if float(r["gpu_ms"]) >= 0 else float(r["wall_ms"])
        spp, relmse = int(r["spp"]), float(r["relmse"]) - reference
        if relmse <= 0.0:
            raise SystemExit(f"{path}: a relMSE {r['relmse']} at or below its reference's own {reference}")
        sums.setdefault(r["strategy"], []).append((ms / spp, relmse * spp, relmse * ms * 1e-3))
    means = {k: tuple(statistics.mean(x[i] for x in v) for i in range(3)) for k, v in sums.items()}
    return {k: (m[0], m[1], 1.0 / m[2]) for k, m in means.items()}


def recorded_pilots(out):
    """(scene, the recheck's SCENE-auto-SEED.json, the full comparison's per_path, the scene's own strategy, one
    pilot's strategy_choice) for every pilot recorded under `out`."""
    for path in sorted(Path(out).glob("*.csv")):
        if "recheck" in path.stem:
            continue
        scene = path.stem
        full = per_path(path, reference_relmse(path))
        own = strategy_of(json.load((Path(out) / f"{scene}-defaults.json").open())["settings"])
        for table in sorted(Path(out).glob(f"{scene}-auto-*.json")):
            for row in json.load(table.open())["rows"]:
                for choice in row.get("strategy_choice", []):
                    yield scene, table, full, own, choice


def pilots(out):
    """Markdown per recheck seed: each candidate's time per path, error per path and efficiency as the pilot measured
    them over the scene's own's, beside the full comparison's (a pilot that ranks a candidate wrongly shows which
    of the two misled it)."""
    for scene, table, full, own, choice in recorded_pilots(out):
        rows = [c for c in choice["candidates"] if c["measurements"] > 0 and not c["too_slow"]]
        mine = next((c for c in rows if c["strategy"] == own), None)
        if not mine or own not in full:
            continue
        scale = choice.get("candidates_cost_scale", 1.0)  # not in the results of 2026-11-29 and before
        planned = "" if scale == 1.0 else f", planned at {scale:.2f}x the own's time per path"
        if choice.get("calibration_ms", 0.0) > 0.0:  # a GPU's calibration frames (results from 2026-11-30 on)
            line = choice["plan_cost"]
            planned += (f", planned by its calibration frames ({choice['calibration_ms']:.1f} ms): "
                        f"{line['fixed_ms']:.2f} ms a frame and {line['ms_per_path'] * 1e6:.2f} ns a path")
        print(f"\n{scene}, {table.stem}: chose {choice['chosen']}; pilot {choice['pilot_width']}x"
              f"{choice['pilot_height']}, {choice['pilot_spp']} spp a measurement, "
              f"{choice['pilot_ms']:.0f} ms on the engine's clock of a {choice['budget_seconds']:g} s "
              f"budget{planned}\n")
        print("| candidate | measurements | time/own: pilot, comparison | error/own: pilot, comparison | "
              "efficiency/own: pilot, comparison | |")
        print("|---|---:|---:|---:|---:|---|")

        def pilot(c):  # time per measurement, relMSE of the mean of all its measurements x their count
            return c["ms"] / c["measurements"], c["relmse"] * c["measurements"]
        t0, e0 = pilot(mine)
        f0 = full[own]
        for c in sorted(rows, key=lambda c: -c["efficiency"]):
            t, e = pilot(c)
            f = full.get(c["strategy"])
            if not f:
                continue
            mark = ", ".join(m for m, on in (("own", c is mine), ("decided", c["final_measurements"] > 0),
                                             ("chosen", c["strategy"] == choice["chosen"])) if on)
            print(f"| {c['strategy']} | {c['measurements']} | {t / t0:.2f}, {f[0] / f0[0]:.2f} | "
                  f"{e / e0:.2f}, {f[1] / f0[1]:.2f} | {c['efficiency'] / mine['efficiency']:.2f}, "
                  f"{f[2] / f0[2]:.2f} | {mark} |")


def leads(outs):
    """One line per pilot's final-round challenger (see the module's docstring): whether a switch rule at another
    minimum lead would have decided otherwise, against the full comparison's ratio."""
    # pilotSwitches' rule is the 5 % since notebook §52; the 10 % was the rule before.
    print("| results | scene | seed | challenger | lead | 2 s.e. | trimmed lead | 2 s.e. | switch at 10 % | at 5 % | "
          "comparison's lead | chosen |")
    print("|---|---|---:|---|---:|---:|---:|---:|---|---|---:|---|")
    for out in outs:
        for scene, table, full, own, choice in recorded_pilots(out):
            mine = next((c for c in choice["candidates"] if c["strategy"] == own), None)
            if not mine or mine["final_efficiency"] <= 0 or own not in full:
                continue
            for c in choice["candidates"]:
                if c is mine or c["final_measurements"] == 0 or c["final_relmse_ratio_to_own"] <= 0:
                    continue
                lead = c["final_efficiency"] / mine["final_efficiency"]
                error = c["final_relmse_ratio_standard_error"] / c["final_relmse_ratio_to_own"]
                trimmed = c["final_relmse_ratio_without_owns_worst"]
                t_lead = lead * c["final_relmse_ratio_to_own"] / trimmed if trimmed > 0 else None
                t_error = (c["final_relmse_ratio_without_owns_worst_standard_error"] / trimmed
                           if trimmed > 0 else None)

                def switches(minimum):  # AutoStrategy.cpp's pilotSwitches, on both pairings
                    ok = math.log(lead) > max(math.log(minimum), 2 * error)
                    return ok and (t_lead is None or math.log(t_lead) > max(math.log(minimum), 2 * t_error))
                true = full[c["strategy"]][2] / full[own][2] if c["strategy"] in full else float("nan")
                t = f"{t_lead:.3f} | {2 * t_error:.3f}" if t_lead else "- | -"
                print(f"| {Path(out).name} | {scene} | {table.stem.rsplit('-', 1)[1]} | {c['strategy']} | "
                      f"{lead:.3f} | {2 * error:.3f} | {t} | {'yes' if switches(1.1) else 'no'} | "
                      f"{'yes' if switches(1.05) else 'no'} | {true:.2f} | "
                      f"{'yes' if choice['chosen'] == c['strategy'] else 'no'} |")


def main():
    if sys.argv[1] == "--leads":
        leads(sys.argv[2:])
        return
    if sys.argv[1] == "--pilots":
        pilots(sys.argv[2])
        return
    if sys.argv[1] == "--best":
        eff, _ = efficiencies(Path(sys.argv[2]))
        print(best_of(eff))
        return
    def shown(r):
        return f"{r[0]:.2f} [{r[1]:.2f}, {r[2]:.2f}]"

    def counted(chosen):
        tally = {}
        for c in chosen:
            tally[c] = tally.get(c, 0) + 1
        return "; ".join(f"{c} x{n}" for c, n in sorted(tally.items(), key=lambda t: -t[1]))

    print("| scene | strategies | best (full comparison) | best, again | scene's own | own / best | auto chose "
          "(recheck seeds) | auto / best | auto / own |")
    print("|---|---:|---|---:|---|---:|---|---:|---:|")
    rows = scene_rows(sys.argv[1])
    for r in rows:
        print(f"| {r['scene']} | {r['strategies']} | {r['best']} ({r['best_full']:.4g}) | {r['best_again']:.4g} | "
              f"{r['own']} | {shown(r['own_best'])} | {counted(r['chosen'])} | "
              f"{shown(r['auto_best'])} | {shown(r['auto_own'])} |")
    # Below a threshold: the whole 95 % interval of the ratio under it (a measured shortfall, not noise).
    low = [r["scene"] for r in rows if r["auto_best"][2] < 0.9]
    below = [r["scene"] for r in rows if r["auto_own"][2] < 1.0]
    print()
    print(f"{rows[0]['seeds'] if rows else 0} recheck seeds; 95 % intervals of each ratio (delta method over seeds); "
          "each relMSE less its reference's own (per scene: "
          + ", ".join(f"{r['scene']} {r['reference_share']:.2g}" for r in rows) + ")")
    print(f"auto below 0.9x the best (interval wholly below): {', '.join(low) if low else 'none'}; below the "
          f"scene's own strategy (interval wholly below): {', '.join(below) if below else 'none'}")
    print(f"point values below 0.9x the best: "
          f"{', '.join(r['scene'] for r in rows if r['auto_best'][0] < 0.9) or 'none'}; below the scene's own: "
          f"{', '.join(r['scene'] for r in rows if r['auto_own'][0] < 1.0) or 'none'}")


if __name__ == "__main__":
    main()
