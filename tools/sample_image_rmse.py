#!/usr/bin/env python3
"""Relative RMSE of a rendered PNG against an expected PNG over a pixel box (the model's pixels).

Usage: sample_image_rmse.py RENDER.png EXPECTED.png X0 Y0 X1 Y1

Both images must have the same size. Channels are 8-bit values / 255 (RGB; alpha ignored). The
box [X0, X1) x [Y0, Y1) is where the model covers both images. Prints
`rel_rmse=<RMSE / mean expected value> rmse=<RMSE> mean_abs=<mean |difference|>
gain=<k> gain_rel_rmse=<rel. RMSE of k x render> chroma=<mean chromaticity distance>`: k is the
least-squares gain of the render onto the expected image (sum R E / sum R^2), which takes out a
difference of overall brightness (another environment's intensity, another exposure) and keeps
the pattern: colors, coverage, what shows through; chroma is the mean over pixels of the
distance between the two (r, g) chromaticities (r / (r + g + b), g / (r + g + b)), pixels with
both sums above 0.05, which no brightness changes.
Python's standard library only (zlib): decodes 8-bit RGB/RGBA, non-interlaced PNGs.
"""
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, width = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or color not in (2, 6) or interlace:
                sys.exit(f"{path}: only 8-bit RGB/RGBA non-interlaced PNGs are read")
            comps = 3 if color == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * comps
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):  # PNG filters (ISO 15948, 9.2)
            a = line[i - comps] if i >= comps else 0
            b = prev[i]
            c = prev[i - comps] if i >= comps else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    return width, height, comps, rows


def chroma(p, q):
    """Distance of the (r, g) chromaticities of two RGB values; None unless both sums > 0.05."""
    sp, sq = sum(p), sum(q)
    if sp <= 0.05 or sq <= 0.05:
        return None
    return ((p[0] / sp - q[0] / sq) ** 2 + (p[1] / sp - q[1] / sq) ** 2) ** 0.5


def main():
    if len(sys.argv) != 7:
        sys.exit(__doc__)
    w1, h1, c1, a = read_png(sys.argv[1])
    w2, h2, c2, b = read_png(sys.argv[2])
    if (w1, h1) != (w2, h2):
        sys.exit(f"sizes differ: {w1}x{h1} and {w2}x{h2}")
    x0, y0, x1, y1 = map(int, sys.argv[3:])
    se = ae = ref = 0.0
    n = 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            for k in range(3):
                p, q = a[y][x * c1 + k] / 255.0, b[y][x * c2 + k] / 255.0
                se += (p - q) ** 2
                ae += abs(p - q)
                ref += q
                n += 1
    rmse = (se / n) ** 0.5
    re = rr = 0.0
    cs, nc = 0.0, 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            p = [a[y][x * c1 + k] / 255.0 for k in range(3)]
            q = [b[y][x * c2 + k] / 255.0 for k in range(3)]
            re += sum(pi * qi for pi, qi in zip(p, q))
            rr += sum(pi * pi for pi in p)
            c = chroma(p, q)
            if c is not None:
                cs += c
                nc += 1
    gain = re / rr if rr > 0.0 else 0.0
    gse = 0.0
    for y in range(y0, y1):
        for x in range(x0, x1):
            for k in range(3):
                gse += (gain * a[y][x * c1 + k] / 255.0 - b[y][x * c2 + k] / 255.0) ** 2
    grel = (gse / n) ** 0.5 / (ref / n)
    print(f"rel_rmse={rmse / (ref / n):.4f} rmse={rmse:.4f} mean_abs={ae / n:.4f} "
          f"gain={gain:.3f} gain_rel_rmse={grel:.4f} chroma={cs / max(nc, 1):.4f}")


if __name__ == "__main__":
    main()
