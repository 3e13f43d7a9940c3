# Writes a torus of major radius 0.5 and minor radius 0.2 around the y axis:
# 64 × 24 quads = 3072 triangles, with normals and (u, v) coordinates.
import math
NU, NV, R, r = 64, 24, 0.5, 0.2
out = ["# Torus, major radius 0.5, minor radius 0.2, axis +y, centred at the origin.",
       f"# {NU} x {NV} quads = {2*NU*NV} triangles; generated for the `stereo` built-in scene.",
       "o torus"]
for i in range(NU + 1):
    u = 2 * math.pi * i / NU
    for j in range(NV + 1):
        v = 2 * math.pi * j / NV
        n = (math.cos(v) * math.cos(u), math.sin(v), math.cos(v) * math.sin(u))
        p = ((R + r * math.cos(v)) * math.cos(u), r * math.sin(v), (R + r * math.cos(v)) * math.sin(u))
        out.append("v %.5f %.5f %.5f" % p)
for i in range(NU + 1):
    for j in range(NV + 1):
        u = 2 * math.pi * i / NU; v = 2 * math.pi * j / NV
        out.append("vn %.5f %.5f %.5f" % (math.cos(v) * math.cos(u), math.sin(v), math.cos(v) * math.sin(u)))
for i in range(NU + 1):
    for j in range(NV + 1):
        out.append("vt %.4f %.4f" % (i / NU, j / NV))
def idx(i, j): return i * (NV + 1) + j + 1
for i in range(NU):
    for j in range(NV):
        a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
        # Counter-clockwise seen from outside: the outward normal is (∂p/∂v) × (∂p/∂u).
        for tri in ((a, d, c), (a, c, b)):
            out.append("f " + " ".join(f"{k}/{k}/{k}" for k in tri))
open("torus.obj", "w").write("\n".join(out) + "\n")
