#!/usr/bin/env python3
"""Renders the independent reference for `raytracer/tests/mitsuba_cornell.rs`.

Mitsuba 3's own Cornell box (`mitsuba.cornell_box()`), path tracer, max depth 65
(unlimited in practice), Russian roulette from depth 5, box reconstruction filter
(each sample counts for its own pixel, as in our renderer), 256x256. The image is
rendered in independent passes with different seeds; the mean of the passes is the
reference and the spread between passes gives the variance of that mean.

    python3 -m venv .venv && .venv/bin/pip install mitsuba==3.9.1 numpy
    .venv/bin/python raytracer/tests/data/make_mitsuba_reference.py --passes 16 --pass-spp 128

writes cornell-mitsuba.exr (mean) and cornell-mitsuba-variance.exr (variance of the mean).
"""
import argparse
import json
import os

import mitsuba as mi
import numpy as np


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--variant", default="scalar_rgb")
    ap.add_argument("--passes", type=int, default=16)
    ap.add_argument("--pass-spp", type=int, default=128)
    ap.add_argument("--out", default=os.path.dirname(os.path.abspath(__file__)))
    a = ap.parse_args()
    mi.set_variant(a.variant)
    d = mi.cornell_box()
    d["integrator"] = {"type": "path", "max_depth": 65, "rr_depth": 5}
    d["sensor"]["film"]["rfilter"] = {"type": "box"}
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
        os.path.join(a.out, "cornell-mitsuba.exr"))
    mi.Bitmap(var_of_mean.astype(np.float32), pixel_format=mi.Bitmap.PixelFormat.RGB).write(
        os.path.join(a.out, "cornell-mitsuba-variance.exr"))
    meta = dict(mitsuba=mi.__version__, variant=a.variant, spp=a.passes * a.pass_spp, passes=a.passes,
                max_depth=65, rr_depth=5, rfilter="box", mean_rgb=mean.mean(axis=(0, 1)).tolist())
    with open(os.path.join(a.out, "cornell-mitsuba.json"), "w") as f:
        json.dump(meta, f, indent=1)
    print(json.dumps(meta))


if __name__ == "__main__":
    main()
