#!/usr/bin/env python3
"""Times Mitsuba 3's path tracer on its Cornell box with the settings of `lesson11 bench`
(256x256, max depth 65, Russian roulette from depth 5, box filter), so the two can be
compared side by side on one machine:

    .venv/bin/python raytracer/tests/data/time_mitsuba_cornell.py llvm_ad_rgb 256
    cargo run --release -p lesson11 -- bench --no-rays --equal-time 0 --spp 256

llvm_ad_rgb needs LLVM 19 (apt-get install libllvm19); scalar_rgb needs nothing.
"""
import os
import sys
import time

os.environ.setdefault("DRJIT_LIBLLVM_PATH", "/usr/lib/x86_64-linux-gnu/libLLVM-19.so")
import drjit as dr  # noqa: E402
import mitsuba as mi  # noqa: E402

variant = sys.argv[1] if len(sys.argv) > 1 else "llvm_ad_rgb"
spp = int(sys.argv[2]) if len(sys.argv) > 2 else 256
mi.set_variant(variant)
d = mi.cornell_box()
d["integrator"] = {"type": "path", "max_depth": 65, "rr_depth": 5}
d["sensor"]["film"]["rfilter"] = {"type": "box"}
scene = mi.load_dict(d)
img = mi.render(scene, spp=16, seed=99)  # warm-up: JIT compilation
dr.eval(img)
dr.sync_thread()
best = float("inf")
for r in range(3):
    t = time.perf_counter()
    img = mi.render(scene, spp=spp, seed=r)
    dr.eval(img)
    dr.sync_thread()
    best = min(best, time.perf_counter() - t)
print(f"Mitsuba {mi.__version__} {variant}: {spp} spp in {best:.2f} s = {256 * 256 * spp / best / 1e6:.2f} M samples/s")
