#!/usr/bin/env python3
"""relMSE of one linear PFM against another, as Common/Image/Metrics.h defines it: the mean over pixels and
channels of (I - R)^2 / (R^2 + 0.01). Usage: pfm_relmse.py TEST.pfm REFERENCE.pfm (same size)."""
import struct
import sys


def read_pfm(path):
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            sys.exit(f"error: {path} is not a colour PFM")
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        count = width * height * 3
        values = struct.unpack(("<" if scale < 0 else ">") + f"{count}f", f.read(4 * count))
    return width, height, values


def main(test_path, reference_path):
    w, h, test = read_pfm(test_path)
    rw, rh, reference = read_pfm(reference_path)
    if (w, h) != (rw, rh):
        sys.exit(f"error: {test_path} is {w}x{h}, {reference_path} is {rw}x{rh}")
    total = sum((t - r) ** 2 / (r * r + 0.01) for t, r in zip(test, reference))
    print(total / len(test))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
