#!/usr/bin/env python3
"""Builds the seed corpora of the fuzzers (fuzz/) in OUT, never in the project: scene files from
samples/scenes; self-contained GLBs packed from the shared assets' glTF files (their .bin buffers
and images embedded); small Radiance .hdr files resampled from the shared environments and
re-encoded with RLE, flat and old-style-run scanlines mixed; the shared assets' small PNGs; a few
PFMs. The committed regression inputs of tests/fuzz/<target> are added too.

Usage: python3 scripts/fuzz_seeds.py OUT [ASSETS]   (ASSETS defaults to ../shared/assets)
"""
import json
import os
import shutil
import struct
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def write(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data)


def pack_glb(gltf_path, max_bytes=256 * 1024):
    """The .gltf at gltf_path with every external buffer and image moved into one BIN chunk."""
    base = os.path.dirname(gltf_path)
    with open(gltf_path, "rb") as f:
        j = json.load(f)
    bin_data = bytearray()
    views = j.setdefault("bufferViews", [])
    offsets = []
    for b in j.get("buffers", []):
        uri = b.pop("uri", None)
        if uri is None or uri.startswith("data:"):
            return None
        with open(os.path.join(base, uri), "rb") as f:
            data = f.read()
        offsets.append(len(bin_data))
        bin_data += data
        while len(bin_data) % 4:
            bin_data.append(0)
    for v in views:  # every view now refers to the single buffer 0
        v["byteOffset"] = v.get("byteOffset", 0) + offsets[v.get("buffer", 0)]
        v["buffer"] = 0
    for im in j.get("images", []):
        uri = im.pop("uri", None)
        if uri is None:
            continue
        if uri.startswith("data:"):
            return None
        with open(os.path.join(base, uri), "rb") as f:
            data = f.read()
        views.append({"buffer": 0, "byteOffset": len(bin_data), "byteLength": len(data)})
        im["bufferView"] = len(views) - 1
        im["mimeType"] = "image/png" if uri.lower().endswith(".png") else "image/jpeg"
        bin_data += data
        while len(bin_data) % 4:
            bin_data.append(0)
    if not views:
        del j["bufferViews"]
    j["buffers"] = [{"byteLength": len(bin_data)}] if bin_data else []
    if not j["buffers"]:
        del j["buffers"]
    text = json.dumps(j, separators=(",", ":")).encode()
    while len(text) % 4:
        text += b" "
    out = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + (8 + len(bin_data) if bin_data else 0))
    out += struct.pack("<II", len(text), 0x4E4F534A) + text
    if bin_data:
        out += struct.pack("<II", len(bin_data), 0x004E4942) + bytes(bin_data)
    return out if len(out) <= max_bytes else None


def read_rgbe(path):
    """Decodes a run-length encoded Radiance file into rows of (r, g, b, e) tuples."""
    with open(path, "rb") as f:
        data = f.read()
    pos = data.index(b"\n\n") + 2
    end = data.index(b"\n", pos)
    _, h, _, w = data[pos:end].split()
    w, h, pos = int(w), int(h), end + 1
    rows = []
    for _ in range(h):
        assert data[pos] == 2 and data[pos + 1] == 2, "expects RLE scanlines"
        pos += 4
        comps = []
        for _c in range(4):
            vals = bytearray()
            while len(vals) < w:
                n = data[pos]
                pos += 1
                if n > 128:
                    vals += bytes([data[pos]]) * (n - 128)
                    pos += 1
                else:
                    vals += data[pos:pos + n]
                    pos += n
            comps.append(vals)
        rows.append(list(zip(*comps)))
    return w, h, rows


def encode_rgbe_line(px, mode):
    if mode == 0:  # RLE, literals only (runs appear as the fuzzer mutates)
        out = bytearray([2, 2, len(px) >> 8, len(px) & 255])
        for c in range(4):
            vals = [p[c] for p in px]
            for i in range(0, len(vals), 128):
                chunk = vals[i:i + 128]
                out.append(len(chunk))
                out += bytes(chunk)
        return bytes(out)
    out = bytearray()
    i = 0
    while i < len(px):
        out += bytes(px[i])
        n = 0
        while mode == 2 and i + 1 + n < len(px) and px[i + 1 + n] == px[i] and n < 255:
            n += 1
        if n:
            out += bytes([1, 1, 1, n])
        i += 1 + n
    return bytes(out)


def hdr_seed(src, w=32):
    sw, sh, rows = read_rgbe(src)
    h = w // 2
    small = [[rows[y * sh // h][x * sw // w] for x in range(w)] for y in range(h)]
    raster = b"".join(encode_rgbe_line(r, y % 3) for y, r in enumerate(small))
    return b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (h, w) + raster


def main():
    out = sys.argv[1]
    assets = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "..", "shared", "assets")
    have_assets = os.path.isdir(assets)
    counts = {}

    def add(target, name, data):
        write(os.path.join(out, target, name), data)
        counts[target] = counts.get(target, 0) + 1

    for name in sorted(os.listdir(os.path.join(ROOT, "samples", "scenes"))):
        if name == "dense_geometry.json":  # 1M triangles to tessellate: ~1 s per run, too slow
            continue
        if not name.endswith(".json"):  # checks/: scenes of the accuracy checks, not samples
            continue
        with open(os.path.join(ROOT, "samples", "scenes", name), "rb") as f:
            add("scene", name, f.read())
    if have_assets:
        for dirpath, _, files in sorted(os.walk(assets)):
            for fn in sorted(files):
                p = os.path.join(dirpath, fn)
                if fn.endswith(".gltf"):
                    try:
                        glb = pack_glb(p)
                    except (OSError, ValueError, KeyError, IndexError):
                        glb = None
                    if glb:
                        add("gltf", fn[:-5] + ".glb", glb)
                elif fn.endswith(".glb") and os.path.getsize(p) <= 256 * 1024:
                    with open(p, "rb") as f:
                        add("gltf", fn, f.read())
                elif fn.endswith(".png") and os.path.getsize(p) <= 64 * 1024:
                    with open(p, "rb") as f:
                        add("png", fn, f.read())
                elif fn.endswith(".hdr"):
                    add("hdr", fn, hdr_seed(p))
    for w, h in [(1, 1), (3, 2), (5, 4)]:
        vals = [float(i) * 0.25 - 1.0 for i in range(w * h * 3)]
        add("pfm", "le_%dx%d.pfm" % (w, h), b"PF\n%d %d\n-1.0\n" % (w, h) + struct.pack("<%df" % len(vals), *vals))
        add("pfm", "be_%dx%d.pfm" % (w, h), b"Pf\n%d %d\n1.0\n" % (w, h) + struct.pack(">%df" % (w * h), *vals[: w * h]))
    for target in ("scene", "gltf", "hdr", "pfm", "png"):
        reg = os.path.join(ROOT, "tests", "fuzz", target)
        if os.path.isdir(reg):
            for fn in sorted(os.listdir(reg)):
                shutil.copy(os.path.join(reg, fn), os.path.join(out, target, "regression_" + fn))
                counts[target] = counts.get(target, 0) + 1
    print("seeds: " + ", ".join("%s %d" % kv for kv in sorted(counts.items())) +
          ("" if have_assets else " (no shared assets at %s)" % assets))


if __name__ == "__main__":
    main()
