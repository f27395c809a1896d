# Issue 39's once-by-hand check that Blender reads the project's EXR files: loads each EXR given after "--" with
# Blender's own image reader and prints its format, size, pixel type, mean and centre pixel (Blender's rows run
# bottom-up, as a PFM's do), to set beside the same render's PFM.
#   blender -b --factory-startup --python tests/Bench/blender_exr_check.py -- a.exr [b.exr ...]
import sys

import bpy

for path in sys.argv[sys.argv.index("--") + 1:]:
    img = bpy.data.images.load(path)
    w, h = img.size
    px = list(img.pixels)
    n = w * h
    mean = [sum(px[c::4]) / n for c in range(3)]
    i = ((h // 2) * w + w // 2) * 4
    print(f"blender {bpy.app.version_string}: {path}: {img.file_format} {w}x{h} "
          f"{'float' if img.is_float else 'byte'} mean {' '.join(f'{m:.6f}' for m in mean)} "
          f"centre {' '.join(f'{c:.6f}' for c in px[i:i + 3])}")
