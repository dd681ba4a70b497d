"""PSNR on the rim of the benchmark's --dump pictures against the 4x4 truth, and of the
experiment's traces (tracer-experiment.patch). Usage:
  python3 rim_bound.py MESH RUN0 RUN1 RUN2 RUN3 RUN4
RUNk: the --dump folder of the run with RF_EXP=k (RUN0: the unpatched tracer, with the DIR rows)."""
import glob
import sys

import numpy as np
from PIL import Image


def load(path):
    return np.asarray(Image.open(path).convert("RGB"), dtype=np.float64) / 255.0


def psnr(a, b, mask):
    return 10.0 * np.log10(1.0 / ((a - b) ** 2)[mask].mean())


mesh, run0, run1, run2, run3, run4 = sys.argv[1:7]
truth = load(f"{run0}/{mesh}_512_reference_full_ss.png")
coverage = load(f"{run2}/{mesh}_512_reference_full_ss.png")[..., 0]
centre_hit = load(f"{run2}/{mesh}_512_reference_full.png")[..., 0] > 0.5
eps = 0.5 / 255.0
rim = (coverage > eps) & (coverage < 1.0 - eps) & centre_hit
rest = (coverage >= 1.0 - eps) & centre_hit
print(f"{mesh}: {rim.sum()} rim pixels, {rest.sum()} others")
for label, run in (("one exact colour per pixel, exact coverage", run1),
                   ("4 exact rays at the 4x sample positions", run3),
                   ("8 exact rays at the 8x sample positions", run4)):
    picture = load(f"{run}/{mesh}_512_reference_full_ss.png")
    print(f"  {label:45s} rim {psnr(picture, truth, rim):5.1f}  rest {psnr(picture, truth, rest):5.1f}")
for path in sorted(glob.glob(f"{run0}/{mesh}_512_DIR*.png")):
    picture = load(path)
    print(f"  {path.split('/')[-1]:45s} rim {psnr(picture, truth, rim):5.1f}  rest {psnr(picture, truth, rest):5.1f}")
