#!/usr/bin/env python3
"""Carries a folder of linear PFM images (an --images folder of --compare) back from the lent GPU machine, whose
files come back at most 16 MiB each: packs them as float16 into compressed .npz files of at most MAX_MB of raw
data each, and unpacks them into PFMs (float32 again) beside their images.json. Half precision is for drawing
the images and their error images; every figure's numbers come from the runs' own JSON.

    pfm_pack.py pack FOLDER PREFIX [MAX_MB]   writes PREFIX-0.npz, PREFIX-1.npz, ... (default MAX_MB 12)
    pfm_pack.py unpack FOLDER NPZ...          writes each image of the NPZs into FOLDER as a PFM
"""
import os
import sys

import numpy as np


def read_pfm(path):
    with open(path, "rb") as f:
        if f.readline().strip() != b"PF":
            raise SystemExit(f"{path}: not an RGB PFM")
        width, height = (int(v) for v in f.readline().split())
        scale = float(f.readline())
        data = np.frombuffer(f.read(), dtype="<f4" if scale < 0 else ">f4", count=width * height * 3)
    return data.reshape(height, width, 3)  # rows as stored: bottom to top


def write_pfm(path, rows):
    height, width = rows.shape[:2]
    with open(path, "wb") as f:
        f.write(f"PF\n{width} {height}\n-1.0\n".encode())
        f.write(rows.astype("<f4").tobytes())


def pack(folder, prefix, max_mb=12.0):
    names = sorted(n for n in os.listdir(folder) if n.endswith(".pfm"))
    batch, size, part = {}, 0, 0
    for name in names:
        image = read_pfm(os.path.join(folder, name)).astype(np.float16)
        if batch and size + image.nbytes > max_mb * 1e6:
            np.savez_compressed(f"{prefix}-{part}.npz", **batch)
            batch, size, part = {}, 0, part + 1
        batch[name] = image
        size += image.nbytes
    if batch:
        np.savez_compressed(f"{prefix}-{part}.npz", **batch)


def unpack(folder, archives):
    os.makedirs(folder, exist_ok=True)
    for archive in archives:
        with np.load(archive) as images:
            for name in images.files:
                write_pfm(os.path.join(folder, os.path.basename(name)), images[name].astype(np.float32))


if __name__ == "__main__":
    if len(sys.argv) >= 4 and sys.argv[1] == "pack":
        pack(sys.argv[2], sys.argv[3], *(float(v) for v in sys.argv[4:5]))
    elif len(sys.argv) >= 4 and sys.argv[1] == "unpack":
        unpack(sys.argv[2], sys.argv[3:])
    else:
        sys.exit(__doc__)
