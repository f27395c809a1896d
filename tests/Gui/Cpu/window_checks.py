#!/usr/bin/env python3
"""Checks on what ray-tracing-cpu's window left behind: its --screenshot (ImageMagick reads it) and its
--state-json (panel settings, the image on screen, timings, GPU status, pane layout in pixels).

  window_checks.py screenshot SHOT.png STATE.json RENDER.png WIDTH HEIGHT
      the screenshot is WIDTHxHEIGHT and not blank; its image pane shows RENDER.png (the same render saved
      through Save image); the image pane and the panel differ
  window_checks.py timings STATE.json gpu|no-gpu
      single and multi core timed the same scene and spp; the GPU did too (gpu), or has no row and a
      reason why it is unavailable (no-gpu)
  window_checks.py settled STATE.json
      the image on screen is complete and was rendered with the panel's settings; no render failed
  window_checks.py headless-args STATE.json
      prints the ray-tracing-cpu --headless flags that render the image on screen
"""
import json
import re
import subprocess
import sys
import tempfile


def fail(message):
    print("FAIL:", message)
    sys.exit(1)


def magick(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout.strip()


def rmse(a, b, size, workdir):
    """Normalised RMSE of two images after both are box-filtered to size x size (a pixel of misalignment
    between the window's nearest-neighbour magnification and the reference does not count)."""
    sa, sb = f"{workdir}/a.png", f"{workdir}/b.png"
    magick("convert", a, "-alpha", "off", "-scale", f"{size}x{size}!", sa)
    magick("convert", b, "-alpha", "off", "-scale", f"{size}x{size}!", sb)
    result = subprocess.run(["compare", "-metric", "RMSE", sa, sb, "null:"], capture_output=True, text=True)
    match = re.search(r"\(([0-9.eE+-]+)\)", result.stderr)
    if not match:
        fail(f"compare said: {result.stderr}")
    return float(match.group(1))


def crop(image, rect, out):
    x, y, w, h = rect
    if w <= 0 or h <= 0:
        fail(f"empty rectangle {rect}")
    magick("convert", image, "-crop", f"{w}x{h}+{x}+{y}", "+repage", out)
    return out


def screenshot(shot, state_path, render, width, height):
    state = json.load(open(state_path))
    size = magick("identify", "-format", "%w %h", shot)
    if size != f"{width} {height}":
        fail(f"screenshot is {size}, the window {width} {height}")
    spread = float(magick("convert", shot, "-format", "%[fx:standard_deviation]", "info:"))
    if spread < 0.05:
        fail(f"screenshot is nearly blank (standard deviation {spread:.4f})")
    layout = state["layout"]
    with tempfile.TemporaryDirectory() as work:
        image = crop(shot, layout["image"], f"{work}/image.png")
        panel = crop(shot, layout["panel"], f"{work}/panel.png")
        shown = rmse(image, render, 24, work)
        if shown > 0.04:
            fail(f"the image pane does not show the render (RMSE {shown:.4f} against Save image's PNG)")
        apart = rmse(image, panel, 64, work)
        if apart < 0.08:
            fail(f"the image pane looks like the panel (RMSE {apart:.4f})")
    print(f"screenshot ok: {size}, deviation {spread:.3f}, image pane vs render RMSE {shown:.4f}, "
          f"vs panel {apart:.4f}")


def timings(state_path, expect):
    state = json.load(open(state_path))
    rows = {}
    for t in state["timings"]:
        rows.setdefault((t["scene"], t["width"], t["height"], t["spp"]), {})[t["engine"]] = t
    full = [k for k, engines in rows.items() if "single" in engines and "multi" in engines]
    if not full:
        fail(f"no work timed on both single and multi core: {sorted(rows)}")
    key = full[-1]
    for engine, t in rows[key].items():
        if not (t["seconds"] > 0 and t["mpaths_per_second"] > 0):
            fail(f"{engine} has no time or Mpaths/s: {t}")
        if not t["build_seconds"] >= 0:
            fail(f"{engine} has no build time: {t}")
        # The CPU engines compile nothing; the GPU engine's first render of a pipeline compiles it, and says so
        # in its own column, apart from the render's time.
        if engine != "gpu" and (t["compiled"] or t["compile_seconds"] is not None):
            fail(f"{engine} reports a compilation: {t}")
        if engine == "gpu" and not (t["compiled"] and t["compile_seconds"] > 0):
            fail(f"the GPU's first render of this pipeline does not report its compilation: {t}")
    gpu = state["gpu"]
    if expect == "gpu":
        if gpu["state"] != "ready":
            fail(f"the GPU engine is {gpu['state']}: {gpu['detail']}")
        if "gpu" not in rows[key]:
            fail(f"no GPU timing beside single and multi core for {key}")
    else:
        if gpu["state"] != "unavailable" or not gpu["detail"]:
            fail(f"the GPU engine should be unavailable with a reason: {gpu}")
        if any("gpu" in engines for engines in rows.values()):
            fail("a GPU timing exists although the GPU engine is unavailable")
    print(f"timings ok: {key} on {sorted(rows[key])}; GPU {gpu['state']}: {gpu['detail']}")


def settled(state_path):
    state = json.load(open(state_path))
    if state["failed_renders"]:
        fail(f"{state['failed_renders']} render(s) failed: {state['message']}")
    image = state["image"]
    if not image or not image["complete"]:
        fail(f"the image on screen is not a finished render: {image}")
    if not state["image_matches_panel"] or image["settings"] != {k: v for k, v in state["panel"].items()
                                                              if k not in ("engine", "loop", "heatmap", "memory_bytes")}:
        fail(f"the image on screen was rendered with {image['settings']}, the panel shows {state['panel']}")
    print(f"settled ok: {image['settings']['scene']} depth {image['settings']['depth']} on {image['engine']}")


def headless_args(state_path):
    s = json.load(open(state_path))["image"]["settings"]
    args = ["--scene", s["scene"], "--spp", s["spp"], "--depth", s["depth"], "--width", s["width"],
            "--aspect", repr(s["aspect"]), "--sampling", s["sampling"], "--estimator", s["estimator"],
            "--russian-roulette", s["russian_roulette"], "--light-sampler", s["light_sampler"],
            "--light-selection", s["light_selection"],
            "--unidirectional-light", "on" if s["unidirectional_light"] else "off", "--seed", s["seed"]]
    if s["count"] >= 0:
        args += ["--count", s["count"]]
    print(" ".join(str(a) for a in args))


def gpu_ready(state_path):
    """Exit status 0 when the window's GPU engine started (a ray-tracing device exists), 1 when not."""
    sys.exit(0 if json.load(open(state_path))["gpu"]["state"] == "ready" else 1)


if __name__ == "__main__":
    command, *rest = sys.argv[1:]
    {"screenshot": lambda: screenshot(rest[0], rest[1], rest[2], rest[3], rest[4]),
     "timings": lambda: timings(rest[0], rest[1]),
     "settled": lambda: settled(rest[0]),
     "headless-args": lambda: headless_args(rest[0]),
     "gpu-ready": lambda: gpu_ready(rest[0])}[command]()
