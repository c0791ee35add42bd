#!/usr/bin/env python3
"""A blended glTF model against its sample image over the sample viewer's own background.

Usage: blend_composite.py BLEND.pfm OPAQUE.pfm EMPTY.pfm OPAQUE.png EXPECTED.png BACKGROUND.png
                          X0 Y0 X1 Y1

Through a blended surface an image shows its background, and the Asset Generator's sample images
were made in another viewer's environment: comparing a render with them compares backgrounds.
This takes the background out. From three linear renders of the model by halfvec under one
environment, the model as it is (BLEND), with every material made opaque (OPAQUE) and with no
model at all (EMPTY), each pixel's coverage by the blended surface is the least-squares
a = (BLEND - EMPTY) . (OPAQUE - EMPTY) / |OPAQUE - EMPTY|^2, clamped to [0, 1] (halfvec blends
a * surface + (1 - a) * background in linear radiance). The sample viewer blends the displayed
values instead, so the prediction of the sample image is
  P = a * g * OPAQUE.png + (1 - a) * BACKGROUND.png
with BACKGROUND.png the sample viewer's background alone (the same camera, every fragment
discarded) and g the least-squares gain of the surface term (their environment lights the surface
otherwise than ours). Pixels whose opaque and empty renders are closer than 0.02 in linear
radiance carry no coverage and are left out.

Prints, over the box [X0, X1) x [Y0, Y1): the mean coverage a, the gain g, the relative RMSE of
P against EXPECTED.png (RMSE / mean expected value) and the mean (r, g) chromaticity distance,
then the same two measures for controls: a = 1 (the surface drawn opaque) and a = 0 (not drawn).
Python's standard library only.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ibl_bias import read_pfm  # noqa: E402
from sample_image_rmse import chroma, read_png  # noqa: E402


def png_rgb(path):
    w, h, c, rows = read_png(path)
    return w, h, [[[rows[y][x * c + k] / 255.0 for k in range(3)] for x in range(w)]
                  for y in range(h)]


def measures(pixels, coverage, gain):
    se = ref = 0.0
    n = 0
    cs, nc = 0.0, 0
    for (d, bt, ct), a in zip(pixels, coverage):
        p = [a * gain * d[k] + (1.0 - a) * bt[k] for k in range(3)]
        for k in range(3):
            se += (p[k] - ct[k]) ** 2
            ref += ct[k]
            n += 1
        c = chroma(p, ct)
        if c is not None:
            cs += c
            nc += 1
    return (se / n) ** 0.5 / (ref / n), cs / max(nc, 1)


def fit_gain(pixels, coverage):
    num = den = 0.0
    for (d, bt, ct), a in zip(pixels, coverage):
        for k in range(3):
            num += a * d[k] * (ct[k] - (1.0 - a) * bt[k])
            den += (a * d[k]) ** 2
    return num / den if den > 0.0 else 0.0


def main():
    if len(sys.argv) != 11:
        sys.exit(__doc__)
    blend, opaque, empty = (read_pfm(p)[2] for p in sys.argv[1:4])
    disp, expected, background = (png_rgb(p)[2] for p in sys.argv[4:7])
    x0, y0, x1, y1 = map(int, sys.argv[7:])
    pixels, coverage = [], []
    for y in range(y0, y1):
        for x in range(x0, x1):
            c, s, b = blend[y][x], opaque[y][x], empty[y][x]
            ds = [s[k] - b[k] for k in range(3)]
            n2 = sum(v * v for v in ds)
            if n2 < 0.02 ** 2:
                continue
            a = sum((c[k] - b[k]) * ds[k] for k in range(3)) / n2
            coverage.append(min(max(a, 0.0), 1.0))
            pixels.append((disp[y][x], background[y][x], expected[y][x]))
    if not pixels:
        sys.exit("no pixel where the opaque and the empty render differ")
    gain = fit_gain(pixels, coverage)
    rel, chrom = measures(pixels, coverage, gain)
    ones = [1.0] * len(coverage)
    g1 = fit_gain(pixels, ones)
    rel1, chrom1 = measures(pixels, ones, g1)
    rel0, chrom0 = measures(pixels, [0.0] * len(coverage), 0.0)
    print(f"pixels={len(pixels)} coverage={sum(coverage) / len(coverage):.3f} gain={gain:.3f} "
          f"rel_rmse={rel:.4f} chroma={chrom:.4f} | opaque: rel_rmse={rel1:.4f} "
          f"chroma={chrom1:.4f} | not drawn: rel_rmse={rel0:.4f} chroma={chrom0:.4f}")


if __name__ == "__main__":
    main()
