#!/usr/bin/env python3
"""Whether two sets of renders of one scene estimate the same image, within noise: each set is renders of
independent seeds (PFM, same size). The image is cut into BLOCK x BLOCK blocks; per block and channel, the
mean over the block of each render is one sample, and Welch's z compares the two sets' sample means. Prints
the count of |z| above 3 and 4 against what independent normal z would give (0.27 % and 0.006 % of the
tests), the largest |z| with its block, and the relative difference of the whole images' means with its
standard error. Exit status 1 when more than 1 % of the tests exceed |z| = 3 or any exceeds 5.
Usage: pfm_block_z.py [--block 8] A1.pfm A2.pfm ... -- B1.pfm B2.pfm ..."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pfm_relmse import read_pfm  # noqa: E402 (the folder first)


def block_means(path, block):
    w, h, v = read_pfm(path)
    means = {}
    for by in range(h // block):
        for bx in range(w // block):
            for c in range(3):
                total = 0.0
                for y in range(by * block, (by + 1) * block):
                    row = y * w
                    for x in range(bx * block, (bx + 1) * block):
                        total += v[3 * (row + x) + c]
                means[(bx, by, c)] = total / (block * block)
    return (w, h), means


def stats(samples):
    n = len(samples)
    mean = sum(samples) / n
    var = sum((s - mean) ** 2 for s in samples) / (n - 1) if n > 1 else 0.0
    return mean, var, n


def main(args):
    block = 8
    if args[:1] == ["--block"]:
        block = int(args[1])
        args = args[2:]
    if "--" not in args:
        sys.exit(__doc__)
    split = args.index("--")
    a_paths, b_paths = args[:split], args[split + 1:]
    if len(a_paths) < 2 or len(b_paths) < 2:
        sys.exit("error: each set needs at least two renders")
    a = [block_means(p, block) for p in a_paths]
    b = [block_means(p, block) for p in b_paths]
    sizes = {m[0] for m in a + b}
    if len(sizes) != 1:
        sys.exit(f"error: the renders differ in size: {sizes}")
    keys = a[0][1].keys()
    over3 = over4 = 0
    worst = (0.0, None)
    whole_a, whole_b = [0.0] * len(a), [0.0] * len(b)
    for k in keys:
        ma, va, na = stats([m[1][k] for m in a])
        mb, vb, nb = stats([m[1][k] for m in b])
        for i, m in enumerate(a):
            whole_a[i] += m[1][k]
        for i, m in enumerate(b):
            whole_b[i] += m[1][k]
        se = math.sqrt(va / na + vb / nb)
        if se == 0.0:
            z = 0.0 if ma == mb else math.inf
        else:
            z = (ma - mb) / se
        over3 += abs(z) > 3
        over4 += abs(z) > 4
        if abs(z) > abs(worst[0]):
            worst = (z, k)
    tests = len(keys)
    ma, va, na = stats(whole_a)
    mb, vb, nb = stats(whole_b)
    rel = (mb - ma) / ma if ma else 0.0
    rel_se = math.sqrt(va / na + vb / nb) / ma if ma else 0.0
    print(f"{tests} block tests ({block}x{block}, 3 channels), {len(a)} against {len(b)} renders: "
          f"|z| > 3: {over3} ({100.0 * over3 / tests:.2f} %, independent normal z: 0.27 %), |z| > 4: {over4}; "
          f"largest |z| {abs(worst[0]):.2f} at block {worst[1]}; "
          f"whole image's mean B/A - 1 = {100 * rel:+.3f} % +- {100 * rel_se:.3f} %")
    return 1 if over3 > 0.01 * tests or abs(worst[0]) > 5 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
