#!/usr/bin/env python3
"""How well the --strategy auto pilot's error estimator ranks candidates, emulated on a --compare --images folder of
one spp count and many seeds (notebook §43). Each candidate's "measurement" is two renders (two seeds) taken as
halves: the pixel's variance from their difference, u = (a - b)^2 / 2, over k measurements, normalised as the pilot
does (by the other candidates' mean, weighted by the inverse of their errors from a first pass by the plain mean:
the scoring between rounds until notebook §45, pilotRelMse), by the own's mean over DENOMINATOR_SEEDS seeds that no measurement uses (a pilot's own render of other seeds),
or by the folder's reference; the candidates' seeds either independent (as the pilot draws them) or the same for
every candidate (common random numbers). Prints, per candidate, the median and the 10 % and 90 % points of its
error over the own's (the first label given) over TRIALS pilots, beside the ratio of their true relMSE against the
reference (the mean over every seed). Standard library only; slow (pure Python), meant for small images.

    ray-tracing-cpu --compare --quiet --engines multi --scene glossy-cornell --width 32 --spp-list 2 --seeds 24 \\
        --rounds 1 --reference-spp 16384 --estimators nee-mis --light-samplers projected,area,solid-angle \\
        --light-selections bvh,power --images DIR
    pilot_estimator.py DIR "projected bvh" [TRIALS]
"""
import json
import random
import statistics
import sys
from pathlib import Path

import pfm_relmse  # beside this script

EPSILON = 0.01  # relMSE's epsilon (Common/Image/Metrics.h)
DENOMINATOR_SEEDS = 8  # the own's renders of other seeds averaged into the third normalisation


def read_pfm(path):
    return list(pfm_relmse.read_pfm(path)[2])


def estimate(images, seeds):
    """Mean image and the variance of that mean per value, from the halves' differences (PilotSums)."""
    k = len(seeds) // 2
    n = len(images[seeds[0]])
    mean, u = [0.0] * n, [0.0] * n
    for m in range(k):
        a, b = images[seeds[2 * m]], images[seeds[2 * m + 1]]
        for i in range(n):
            mean[i] += a[i] + b[i]
            u[i] += 0.5 * (a[i] - b[i]) ** 2
    return [x / (2 * k) for x in mean], [x / k / (2 * k) for x in u]


def main():
    folder, own = Path(sys.argv[1]), sys.argv[2]
    trials = int(sys.argv[3]) if len(sys.argv) > 3 else 30
    index = json.loads((folder / "images.json").read_text())
    reference = read_pfm(folder / index["reference"]["path"])
    images = {}
    for image in index["images"]:
        images.setdefault(image["label"], {})[image["seed"]] = read_pfm(folder / image["path"])
    labels = sorted(images)
    if own not in labels:
        raise SystemExit(f"no label {own!r} among {labels}")
    seeds = sorted(images[own])

    def true_relmse(x):
        return sum((v - r) ** 2 / (r * r + EPSILON) for v, r in zip(x, reference)) / len(x)
    truth = {l: statistics.mean(true_relmse(images[l][s]) for s in images[l]) for l in labels}
    rng = random.Random(1)
    for paired in (False, True):
        for k in (1, 3, 6):
            if 2 * k > len(seeds):
                continue
            ratios = {l: ([], [], []) for l in labels if l != own}
            if 2 * k + DENOMINATOR_SEEDS > len(seeds):
                continue
            for _ in range(trials):
                drawn = rng.sample(seeds, 2 * k + DENOMINATOR_SEEDS)
                shared, spare = drawn[:2 * k], drawn[2 * k:]
                unused = [s for s in seeds if s not in spare]
                est = {l: estimate(images[l], shared if paired else rng.sample(unused, 2 * k)) for l in labels}
                own_mean = [sum(images[own][s][i] for s in spare) / len(spare) for i in range(len(reference))]
                errors = {}
                weights = {l: 1.0 for l in labels}
                for _ in range(2):  # that scoring's two passes: the others' plain mean, then weighted by 1/error
                    for l in labels:
                        others, total = [0.0] * len(reference), sum(weights[o] for o in labels if o != l)
                        for o in labels:
                            if o != l:
                                for i, x in enumerate(est[o][0]):
                                    others[i] += weights[o] * x / total
                        variance = est[l][1]
                        errors[l] = tuple(sum(v / (o * o + EPSILON) for v, o in zip(variance, d)) / len(variance)
                                          for d in (others, own_mean, reference))
                    weights = {l: 1.0 / max(errors[l][0], 1e-300) for l in labels}
                for l in ratios:
                    for j in range(3):
                        ratios[l][j].append(errors[l][j] / errors[own][j])
            for l, (pilot, by_spare, by_reference) in ratios.items():
                def shown(v):
                    v = sorted(v)
                    return f"{statistics.median(v):.2f} [{v[len(v) // 10]:.2f}, {v[-1 - len(v) // 10]:.2f}]"
                print(f"{'common' if paired else 'independent'} seeds, k={k}, {l}: the pilot's {shown(pilot)}, "
                      f"the own's other seeds' {shown(by_spare)}, the reference's {shown(by_reference)}, "
                      f"true {truth[l] / truth[own]:.2f}")


if __name__ == "__main__":
    main()
