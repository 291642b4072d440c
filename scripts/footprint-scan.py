#!/usr/bin/env python3
"""The sun's diffuse on a footprint of normal-mapped bumps: the mean over every texel against
the frame's estimates of it (docs/materials.md, "A footprint's bumps").

  scripts/footprint-scan.py

The scene is scripts/scenes.py's normal-mapped floor (egg-crate bumps, slopes up to 0.6 on
each axis, roughness 0.15, f0 0.04), the camera 1.7 m up, the sun 15 degrees up ahead. Per
texel, as the reference shades it: the normal bent so that its reflection of the view stays
above the floor (normal_withValidReflection), the diffuse's energy weight 1 - E_spec at that
normal's view angle and the texel's own gloss (the split-sum table, shaders/env_brdf_table.inc),
times its cosine to the sun. Printed per point of the floor: that mean over 48 x 48 texels of
one bump, and each estimate over it:
  lobe    the pixel's mean normal with the footprint's CLEAN lobe (the frame before)
  texel   the pixel's mean normal with the texels' own gloss
  two     two normals along the view, at +-s/sqrt(2)
  ringN   N normals on a ring at the RMS slope s (the frame without the slopes' kurtosis: six)
  kurt    the mean normal at weight 1 - 1/k and six on a ring at s sqrt(k), k the slopes'
          kurtosis (the frame with it: footprintCentreWeight, footprintRingRadius)
"""
import math
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
TABLE = [float(x.rstrip("f")) for x in re.findall(
    r"[-0-9.e+]+f", open(os.path.join(HERE, "..", "shaders", "env_brdf_table.inc")).read())]
N = 32  # the table's size per axis


def env(nov, gloss):
    """(scale, bias) of the split-sum table, bilinear at its texel centres."""
    x = math.sqrt(min(max(nov, 1e-4), 1.0)) * (N - 1)
    y = min(max(gloss, 0.0), 1.0) * (N - 1)
    i, j = min(int(x), N - 2), min(int(y), N - 2)
    fx, fy = x - i, y - j

    def t(a, b, c):
        return TABLE[2 * (b * N + a) + c]
    return [(1 - fy) * ((1 - fx) * t(i, j, c) + fx * t(i + 1, j, c)) +
            fy * ((1 - fx) * t(i, j + 1, c) + fx * t(i + 1, j + 1, c)) for c in (0, 1)]


def weight(nov, gloss, f0=0.04):
    e = env(nov, gloss)
    return max(0.0, 1.0 - (f0 * e[0] + e[1]))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def normalize(a):
    length = math.sqrt(dot(a, a))
    return [c / length for c in a]


def bend(n, ns, v):
    """normal_withValidReflection of shaders/material.glsl."""
    lift = min(0.9 * dot(ns, v), 0.01)
    r = [2 * dot(n, v) * n[k] - v[k] for k in range(3)]
    up = dot(r, ns)
    if up >= lift:
        return n
    across = [r[k] - ns[k] * up for k in range(3)]
    length = math.sqrt(dot(across, across))
    if length < 1e-6:
        return ns
    lifted = [across[k] * math.sqrt(1 - lift * lift) / length + ns[k] * lift for k in range(3)]
    return normalize([v[k] + lifted[k] for k in range(3)])


def gloss_of_alpha2(alpha2):
    return min(max(math.log2(max(2.0 / alpha2 - 1.0, 1.0)) / 18.0, 0.0), 1.0)


def main():
    up = [0.0, 1.0, 0.0]
    sun = [0.0, math.sin(math.radians(15)), -math.cos(math.radians(15))]
    base_alpha2 = 0.15 ** 4  # roughness 0.15: alpha = roughness^2
    base_gloss = gloss_of_alpha2(base_alpha2)
    k = 48
    slopes = []
    for i in range(k):
        for j in range(k):
            u, w = 2 * math.pi * (i + 0.5) / k, 2 * math.pi * (j + 0.5) / k
            slopes.append((0.6 * math.cos(u) * math.sin(w), 0.6 * math.sin(u) * math.cos(w)))
    variance = sum(a * a + b * b for a, b in slopes) / len(slopes)  # both axes
    lobe_gloss = gloss_of_alpha2(base_alpha2 + variance)
    s = math.sqrt(variance)
    print(f"texels' gloss {base_gloss:.3f}, the footprint's CLEAN gloss {lobe_gloss:.3f}, "
          f"RMS slope {s:.3f}")
    kurtosis = sum((a * a + b * b) ** 2 for a, b in slopes) / len(slopes) / variance ** 2
    print(f"{'point (x, z) m':>16} {'NoV':>6} {'texels':>7} {'lobe':>6} {'texel':>6} {'two':>6} "
          f"{'ring4':>6} {'ring6':>6} {'ring8':>6} {'ring12':>6} {'kurt':>6}")
    for x, z in [(0, -4), (3, -3), (-5, -5), (-10, -10), (0, -20), (-25, -60), (0, -60),
                 (-60, -60), (0, -150), (-100, -150)]:
        v = normalize([-x, 1.7, -z])
        mean = sum(weight(dot(bend(normalize([-a, 1.0, -b]), up, v), v), base_gloss) *
                   max(dot(bend(normalize([-a, 1.0, -b]), up, v), sun), 0.0)
                   for a, b in slopes) / len(slopes)
        t = normalize([v[0], 0.0, v[2]])
        b = [-t[2], 0.0, t[0]]

        def at(da, db, gloss=base_gloss):
            n = bend(normalize([up[q] + da * t[q] + db * b[q] for q in range(3)]), up, v)
            return weight(max(dot(n, v), 1e-4), gloss) * max(dot(n, sun), 0.0)

        def ring(count, radius=s):
            return sum(at(radius * math.cos(2 * math.pi * c / count),
                          radius * math.sin(2 * math.pi * c / count))
                       for c in range(count)) / count
        nov = dot(up, v)
        centre = 1 - 1 / kurtosis
        row = [at(0, 0, lobe_gloss), at(0, 0), 0.5 * (at(s / math.sqrt(2), 0) + at(-s / math.sqrt(2), 0)),
               ring(4), ring(6), ring(8), ring(12),
               centre * at(0, 0) + (1 - centre) * ring(6, s * math.sqrt(kurtosis))]
        print(f"{str((x, z)):>16} {nov:6.3f} {mean:7.4f} " + " ".join(f"{r / mean:6.2f}" for r in row))


if __name__ == "__main__":
    main()
