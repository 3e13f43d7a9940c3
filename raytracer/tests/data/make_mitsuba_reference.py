#!/usr/bin/env python3
"""Renders the independent references for `raytracer/tests/mitsuba_cornell.rs`.

Mitsuba 3's own Cornell box (`mitsuba.cornell_box()`), path tracer, max depth 65
(unlimited in practice), Russian roulette from depth 5, box reconstruction filter
(each sample counts for its own pixel, as in our renderer), 256x256. The image is
rendered in independent passes with different seeds; the mean of the passes is the
reference and the spread between passes gives the variance of that mean.

    python3 -m venv .venv && .venv/bin/pip install mitsuba==3.9.1 numpy
    # the whole image (cornell-mitsuba.exr, cornell-mitsuba-variance.exr):
    .venv/bin/python raytracer/tests/data/make_mitsuba_reference.py --passes 16 --pass-spp 128
    # the band around the lamp, far more samples (cornell-mitsuba-lamp*.exr):
    .venv/bin/python raytracer/tests/data/make_mitsuba_reference.py --variant llvm_ad_rgb \
        --name cornell-mitsuba-lamp --crop 64 24 128 24 --passes 32 --pass-spp 2048

writes NAME.exr (mean), NAME-variance.exr (variance of the mean) and NAME.json.
With --crop X Y W H only the pixels x in [X, X+W), y in [Y, Y+H) of the 256x256
image are rendered (a box filter makes them identical to the same pixels of the
whole image). llvm_ad_rgb is about three times as fast as scalar_rgb; it needs
LLVM 19 (apt-get install libllvm19), found below.
"""
import argparse
import json
import os

# drjit searches /usr/lib/x86_64-linux-gnu/libLLVM*.so.*; pin LLVM 19 if present
# (with LLVM 14/15 llvm_ad_rgb aborts: "Cannot select ... fminimum").
_LLVM19 = "/usr/lib/x86_64-linux-gnu/libLLVM-19.so"
if "DRJIT_LIBLLVM_PATH" not in os.environ and os.path.exists(_LLVM19):
    os.environ["DRJIT_LIBLLVM_PATH"] = _LLVM19

import mitsuba as mi
import numpy as np


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--variant", default="scalar_rgb")
    ap.add_argument("--passes", type=int, default=16)
    ap.add_argument("--pass-spp", type=int, default=128)
    ap.add_argument("--name", default="cornell-mitsuba")
    ap.add_argument("--crop", type=int, nargs=4, metavar=("X", "Y", "W", "H"))
    ap.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    a = ap.parse_args()
    mi.set_variant(a.variant)
    d = mi.cornell_box()
    d["integrator"] = {"type": "path", "max_depth": 65, "rr_depth": 5}
    d["sensor"]["film"]["rfilter"] = {"type": "box"}
    if a.crop:
        x, y, w, h = a.crop
        d["sensor"]["film"].update(crop_offset_x=x, crop_offset_y=y, crop_width=w, crop_height=h)
    scene = mi.load_dict(d)
    passes = []
    for i in range(a.passes):
        img = np.array(mi.render(scene, spp=a.pass_spp, seed=i), dtype=np.float64)[..., :3]
        passes.append(img)
        print(f"pass {i + 1}/{a.passes}: mean {img.mean(axis=(0, 1))}", flush=True)
    stack = np.stack(passes)
    mean = stack.mean(axis=0)
    var_of_mean = stack.var(axis=0, ddof=1) / len(passes)
    mi.Bitmap(mean.astype(np.float32), pixel_format=mi.Bitmap.PixelFormat.RGB).write(
        os.path.join(a.out, a.name + ".exr"))
    mi.Bitmap(var_of_mean.astype(np.float32), pixel_format=mi.Bitmap.PixelFormat.RGB).write(
        os.path.join(a.out, a.name + "-variance.exr"))
    meta = dict(mitsuba=mi.__version__, variant=a.variant, spp=a.passes * a.pass_spp, passes=a.passes,
                max_depth=65, rr_depth=5, rfilter="box", mean_rgb=mean.mean(axis=(0, 1)).tolist())
    if a.crop:
        meta["crop"] = dict(x=a.crop[0], y=a.crop[1], width=a.crop[2], height=a.crop[3])
    with open(os.path.join(a.out, a.name + ".json"), "w") as f:
        json.dump(meta, f, indent=1)
    print(json.dumps(meta))


if __name__ == "__main__":
    main()
