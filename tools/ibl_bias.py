#!/usr/bin/env python3
"""The two measurements of docs/ibl.md on an engine AOV and the reference's (PFM files from
`halfvec render --aov DIR` and `halfvec reference --aov DIR`), standard library only.

  python3 tools/ibl_bias.py grid SCENE.json ENGINE.pfm REFERENCE.pfm
  python3 tools/ibl_bias.py glint ENGINE.pfm REFERENCE.pfm

grid: engine / reference - 1 of the luminance summed over each sphere of a sphere_grid-like scene
(spheres found by casting the scene camera's rays against the scene file's spheres, so the image
must be rendered from that camera with a square or any aspect at the scene's fov), split by N.V
into "grazing" (0.05 <= N.V < 0.3) and "facing" (N.V >= 0.3), per (roughness, metallic) and summed
over the rough spheres (roughness >= 0.75). The outermost ring (N.V < 0.05) is left out: its
pixels mix with the background.

glint: the brightest 3x3 spot of the reference (a sun's glint), in a 17x17 window around it: the
peak of each image and their ratio, the core (reference >= 1/4 of its peak) and the halo (the rest
of the window) as engine / reference ratios, and the share of the image's squared error in the
window.
"""
import json
import math
import struct
import sys


def read_pfm(path):
    """Rows top to bottom (PFM stores them bottom to top), each a list of (r, g, b)."""
    with open(path, 'rb') as f:
        if f.readline().strip() != b'PF':
            sys.exit('%s: not an RGB PFM file (expected the header "PF")' % path)
        w, h = map(int, f.readline().split())
        order = '<' if float(f.readline()) < 0 else '>'
        data = struct.unpack(order + 'f' * (w * h * 3), f.read(w * h * 12))
    rows = [data[(h - 1 - y) * w * 3:(h - y) * w * 3] for y in range(h)]
    return w, h, [[rows[y][3 * x:3 * x + 3] for x in range(w)] for y in range(h)]


def lum(c):
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def norm(a):
    n = math.sqrt(dot(a, a))
    return [x / n for x in a]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def grid(scene_path, engine_path, ref_path):
    scene = json.load(open(scene_path))
    w, h, eng = read_pfm(engine_path)
    rw, rh, ref = read_pfm(ref_path)
    if (w, h) != (rw, rh):
        sys.exit('%s is %dx%d, %s is %dx%d: expected the same size' %
                 (engine_path, w, h, ref_path, rw, rh))
    cam = scene['camera']
    pos, target = cam['position'], cam['target']
    fwd = norm(sub(target, pos))
    right = norm(cross(fwd, [0, 1, 0]))
    up = cross(right, fwd)
    t = math.tan(math.radians(cam['fov_y_deg']) / 2)
    spheres = [o for o in scene['objects'] if o.get('primitive') == 'sphere']
    bins = {}
    for y in range(h):
        for x in range(w):
            u = (2 * (x + 0.5) / w - 1) * t * w / h
            v = (1 - 2 * (y + 0.5) / h) * t
            d = norm([fwd[i] + u * right[i] + v * up[i] for i in range(3)])
            hit = None
            for s in spheres:
                oc = sub(pos, s['transform']['translation'])
                b = dot(oc, d)
                disc = b * b - dot(oc, oc) + s['radius'] ** 2
                if disc < 0:
                    continue
                dist = -b - math.sqrt(disc)
                if dist > 0 and (hit is None or dist < hit[0]):
                    hit = (dist, s)
            if hit is None:
                continue
            dist, s = hit
            n = norm(sub([pos[i] + dist * d[i] for i in range(3)], s['transform']['translation']))
            nov = -dot(n, d)
            if nov < 0.05:
                continue
            m = s['material']
            key = (m.get('roughness', 0.5), m.get('metallic', 0.0),
                   'grazing' if nov < 0.3 else 'facing')
            e = bins.setdefault(key, [0.0, 0.0, 0])
            e[0] += lum(eng[y][x])
            e[1] += lum(ref[y][x])
            e[2] += 1
    print('roughness metallic region pixels engine/reference-1')
    for k in sorted(bins):
        e = bins[k]
        print('%.2f %.2f %-8s %5d %+.3f' % (k[0], k[1], k[2], e[2], e[0] / e[1] - 1))
    for region in ('grazing', 'facing'):
        se = sum(e[0] for k, e in bins.items() if k[0] >= 0.75 and k[2] == region)
        sr = sum(e[1] for k, e in bins.items() if k[0] >= 0.75 and k[2] == region)
        print('rough (>= 0.75) %s: engine/reference - 1 = %+.3f' % (region, se / sr - 1))


def glint(engine_path, ref_path):
    w, h, eng = read_pfm(engine_path)
    _, _, ref = read_pfm(ref_path)
    E = [[lum(eng[y][x]) for x in range(w)] for y in range(h)]
    R = [[lum(ref[y][x]) for x in range(w)] for y in range(h)]

    def mean3(img, x, y):
        return sum(img[j][i] for j in range(y - 1, y + 2) for i in range(x - 1, x + 2)) / 9

    py, px = max(((y, x) for y in range(1, h - 1) for x in range(1, w - 1)),
                 key=lambda p: mean3(R, p[1], p[0]))
    rad = 8
    win = [(y, x) for y in range(max(py - rad, 0), min(py + rad + 1, h))
           for x in range(max(px - rad, 0), min(px + rad + 1, w))]
    rpk = max(R[y][x] for y, x in win)
    epk = max(E[y][x] for y, x in win)
    print('glint at pixel (%d, %d): reference peak %.1f, engine peak %.1f, ratio %.2f' %
          (px, py, rpk, epk, epk / rpk))
    core = [(y, x) for y, x in win if R[y][x] >= 0.25 * rpk]
    halo = [(y, x) for y, x in win if 0 < R[y][x] < 0.25 * rpk]
    ratios = sorted(E[y][x] / R[y][x] for y, x in halo)
    print('core (reference >= 1/4 of its peak): %d px, engine/reference of the sums %.2f' %
          (len(core), sum(E[y][x] for y, x in core) / sum(R[y][x] for y, x in core)))
    print('halo (the rest of the %dx%d window): %d px, engine/reference median %.2f, 90th '
          'percentile %.2f, max %.2f, of the sums %.2f' %
          (2 * rad + 1, 2 * rad + 1, len(halo), ratios[len(ratios) // 2],
           ratios[int(len(ratios) * 0.9)], ratios[-1],
           sum(E[y][x] for y, x in halo) / sum(R[y][x] for y, x in halo)))
    win_se = sum((E[y][x] - R[y][x]) ** 2 for y, x in win)
    all_se = sum((E[y][x] - R[y][x]) ** 2 for y in range(h) for x in range(w))
    lit = sum(1 for y in range(h) for x in range(w) if R[y][x] > 0)
    mean = sum(map(sum, R)) / lit
    print('squared error in the window: %.1f%% of the image; relative RMSE of the term over lit '
          'pixels %.3f, outside the window %.3f' %
          (100 * win_se / all_se, math.sqrt(all_se / lit) / mean,
           math.sqrt((all_se - win_se) / (lit - len(win))) / mean))


if __name__ == '__main__':
    if len(sys.argv) == 5 and sys.argv[1] == 'grid':
        grid(*sys.argv[2:])
    elif len(sys.argv) == 4 and sys.argv[1] == 'glint':
        glint(*sys.argv[2:])
    else:
        sys.exit(__doc__)
