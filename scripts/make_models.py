#!/usr/bin/env python3
"""Builds the small structural models bundled with voroseal (models/*.ts).

    python3 scripts/make_models.py                  # writes models/folded_layers.ts, models/faulted_layers.ts
    python3 scripts/make_models.py --obj /tmp/m     # also an OBJ twin + render sidecar per model
    python3 scripts/make_models.py --check          # independent check of the written .ts files
    python3 scripts/make_models.py --check FILE.ts  # ... of any GOCAD TSurf file

Standard library only; deterministic: the same bytes on every run (coordinates are rounded
to the millimetre once, when a vertex is created, and everything else is integer bookkeeping).

Models (box 4000 x 3000 x 1000 m, x + 500000, y + 4000000, z from -2000 to -1000, elevation):
  folded_layers.ts   two folded horizons (oblique sinusoidal folds + a dome) => 3 regions.
  faulted_layers.ts  two gently folded horizons cut by one planar normal fault dipping 60 deg
                     (strike 8.5 deg off the y axis), throw 150-190 m => 3 layers x 2 blocks.

How conformity is guaranteed: every surface is a set of strips of vertex *chains* (lists of
vertex ids). Horizons, top and bottom are height fields on a grid of rows y_j and columns
x_i(y_j) that end exactly at the fault trace (the last column *is* the fault trace); box
sides and fault patches are strips between two curves already built (e.g. the bottom edge
and the trace of horizon H1), meshed column by column. A column between two vertices is
made once and cached, so every surface that borders the same segment uses the same chain;
a fault column crossed by horizon cut-offs is the concatenation of its cached pieces. Two
neighbouring chains are joined by a zipper (greedy shortest diagonal), which uses every
vertex of both chains whatever their lengths: no T-junction by construction.

Output: one `GOCAD TSurf 1` object per geological surface (6 box sides, horizons, fault),
one TFACE per surface part (a box side is split by the horizon and fault traces), each
TFACE with its own VRTX list; shared positions are repeated with identical text.
Normals: box sides outward, horizons up, fault towards the hanging wall.

--check re-reads TSurf files (welding by exact coordinates) and verifies: no repeated-vertex,
zero-area or duplicated triangle, no near-coincident distinct vertices, every edge has >= 2
incident triangles, then regions by radial sorting of the triangles around every edge
(like a model builder would), each region closed, and bounded region volumes (divergence
theorem, exact integer arithmetic) adding up to the bounding-box volume; it also counts
surface parts, contact lines and corners with meshreport's definitions.
"""
import argparse
import json
import math
import os
import sys

OFFSET_MM = (500000000, 4000000000, 0)  # UTM-like offset added on output (millimetres)
LX, LY = 4000.0, 3000.0  # box size (m)
ZBOT, ZTOP = -2000.0, -1000.0  # box bottom / top elevation (m)
TARGET = 135.0  # target edge length along box-side and fault columns (m)
OUT = -1  # label of the outside


# ----------------------------------------------------------------------------- mesh building


class Builder:
    """Vertices (integer millimetres, local frame), cached columns, and surfaces made of parts."""

    def __init__(self):
        self.P = []  # (x, y, z) in mm
        self.where = {}  # position -> id, to catch accidental double creation
        self.columns = {}  # (lo, hi) -> chain of ids
        self.surfaces = []  # dicts: name, type, feature, parts

    def vertex(self, x, y, z):
        p = (int(round(x * 1000.0)), int(round(y * 1000.0)), int(round(z * 1000.0)))
        if p in self.where:
            raise RuntimeError("vertex created twice at %r" % (p,))
        self.where[p] = len(self.P)
        self.P.append(p)
        return len(self.P) - 1

    def dist(self, a, b):
        pa, pb = self.P[a], self.P[b]
        return math.sqrt(sum((pa[k] - pb[k]) ** 2 for k in range(3))) / 1000.0

    def column(self, lo, hi):
        """Chain lo -> hi (straight segment), interior points spaced about TARGET; cached."""
        key = (lo, hi)
        if key not in self.columns:
            n = max(1, int(round(self.dist(lo, hi) / TARGET)))
            pa, pb = self.P[lo], self.P[hi]
            chain = [lo]
            for k in range(1, n):
                t = k / n
                chain.append(self.vertex(*((pa[c] + t * (pb[c] - pa[c])) / 1000.0 for c in range(3))))
            chain.append(hi)
            self.columns[key] = chain
        return self.columns[key]

    def chain(self, keys):
        """Concatenation of the cached columns between consecutive key vertices."""
        out = [keys[0]]
        for a, b in zip(keys, keys[1:]):
            out += self.column(a, b)[1:]
        return out

    def area2(self, a, b, c):
        """Twice the area vector of triangle abc (exact integers, mm^2)."""
        pa, pb, pc = self.P[a], self.P[b], self.P[c]
        u = [pb[k] - pa[k] for k in range(3)]
        v = [pc[k] - pa[k] for k in range(3)]
        return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])

    def zipper(self, A, B):
        """Triangles between two chains running the same way (A[0]-B[0] to A[-1]-B[-1])."""
        tris = []
        i = j = 0
        while i < len(A) - 1 or j < len(B) - 1:
            if i == len(A) - 1:
                adv_a = False
            elif j == len(B) - 1:
                adv_a = True
            else:
                adv_a = self.dist(A[i + 1], B[j]) <= self.dist(A[i], B[j + 1])
                # never emit a flat triangle when the other choice is fine
                cand = (A[i], B[j], A[i + 1]) if adv_a else (A[i], B[j], B[j + 1])
                if self.area2(*cand) == (0, 0, 0):
                    adv_a = not adv_a
            if adv_a:
                tris.append((A[i], B[j], A[i + 1]))
                i += 1
            else:
                tris.append((A[i], B[j], B[j + 1]))
                j += 1
        return tris

    def strip(self, chains):
        tris = []
        for A, B in zip(chains, chains[1:]):
            tris += self.zipper(A, B)
        return tris

    def add_part(self, surface, tris, normal, below, above):
        """A surface part; `normal` is the wanted orientation, `below`/`above` the regions on
        the negative / positive side of it."""
        s = sum(sum(self.area2(*t)[k] * normal[k] for t in tris) for k in range(3))
        if s < 0:
            tris = [(a, c, b) for a, b, c in tris]
        surface["parts"].append({"tris": tris, "labels": (below, above)})

    def add_surface(self, name, gtype, feature):
        s = {"name": name, "type": gtype, "feature": feature, "parts": []}
        self.surfaces.append(s)
        return s


def sheet(B, rows, xs_of_row, zfun, prescribed=None):
    """Height-field grid G[i][j]: row j at y = rows[j], columns x = xs_of_row(j)[i], z = zfun(x, y).
    `prescribed[(i, j)]` gives vertex ids already made (fault cut-offs, fault traces)."""
    prescribed = prescribed or {}
    xs = [xs_of_row(j) for j in range(len(rows))]
    m = len(xs[0]) - 1
    G = [[None] * len(rows) for _ in range(m + 1)]
    for j, y in enumerate(rows):
        for i in range(m + 1):
            if (i, j) in prescribed:
                G[i][j] = prescribed[(i, j)]
            else:
                x = xs[j][i]
                G[i][j] = B.vertex(x, y, zfun(x, y))
    return G


def sheet_tris(B, G):
    return B.strip([list(col) for col in G])


def bisect(g, lo, hi):
    """Root of g on [lo, hi] with g(lo) > 0 > g(hi), to the last bit (deterministic)."""
    assert g(lo) > 0 > g(hi), "no sign change"
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid == lo or mid == hi:
            break
        if g(mid) > 0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def check_gap(name, lower, upper, min_gap, points):
    gap = min(upper(x, y) - lower(x, y) for x, y in points)
    if gap < min_gap:
        raise RuntimeError("%s: surfaces only %.1f m apart (need %.1f)" % (name, gap, min_gap))


def sample_points(n=81):
    return [(LX * i / (n - 1), LY * j / (n - 1)) for i in range(n) for j in range(n)]


# ----------------------------------------------------------------------------- folded model


def folded_model():
    c20, s20 = math.cos(math.radians(20.0)), math.sin(math.radians(20.0))

    def fold(x, y):  # cylindrical folds, axes trending N110E, wavelength 2.6 km
        return 110.0 * math.sin(2.0 * math.pi * (x * c20 + y * s20) / 2600.0 + 0.4)

    def dome(x, y):
        return 140.0 * math.exp(-((x - 2700.0) / 650.0) ** 2 - ((y - 1300.0) / 550.0) ** 2)

    def h1(x, y):
        return -1640.0 + fold(x, y) + dome(x, y)

    def h2(x, y):  # folds and dome damped upwards, thickness varying along y
        return -1320.0 + 0.75 * fold(x, y) + 0.8 * dome(x, y) + 30.0 * math.sin(2.0 * math.pi * y / LY)

    pts = sample_points()
    bottom = lambda x, y: ZBOT
    top = lambda x, y: ZTOP
    check_gap("bottom/H1", bottom, h1, 150.0, pts)
    check_gap("H1/H2", h1, h2, 150.0, pts)
    check_gap("H2/top", h2, top, 100.0, pts)

    B = Builder()
    nx, ny = 30, 22
    rows = [LY * j / ny for j in range(ny + 1)]
    full = lambda j: [LX * i / nx for i in range(nx + 1)]
    levels = [bottom, h1, h2, top]
    G = [sheet(B, rows, full, f) for f in levels]  # bottom, H1, H2, top
    m = nx

    def side_strip(layer, cols):
        lo, hi = G[layer], G[layer + 1]
        return B.strip([B.column(lo[i][j], hi[i][j]) for i, j in cols])

    boundary = {}
    for name in ("top", "bottom", "west", "east", "south", "north"):
        boundary[name] = B.add_surface("boundary_" + name, "boundary", "model_boundary")
    B.add_part(boundary["bottom"], sheet_tris(B, G[0]), (0, 0, -1), 0, OUT)
    B.add_part(boundary["top"], sheet_tris(B, G[3]), (0, 0, 1), 2, OUT)
    for layer in range(3):
        B.add_part(boundary["west"], side_strip(layer, [(0, j) for j in range(ny + 1)]), (-1, 0, 0), layer, OUT)
        B.add_part(boundary["east"], side_strip(layer, [(m, j) for j in range(ny + 1)]), (1, 0, 0), layer, OUT)
        B.add_part(boundary["south"], side_strip(layer, [(i, 0) for i in range(m + 1)]), (0, -1, 0), layer, OUT)
        B.add_part(boundary["north"], side_strip(layer, [(i, ny) for i in range(m + 1)]), (0, 1, 0), layer, OUT)
    for k in (1, 2):
        s = B.add_surface("H%d" % k, "horizon", "H%d" % k)
        B.add_part(s, sheet_tris(B, G[k]), (0, 0, 1), k - 1, k)
    # order: horizons first, then the box, like a modeller's surface list
    B.surfaces = B.surfaces[6:] + B.surfaces[:6]
    info = {"n_layers": 3, "regions": {0: 0, 1: 1, 2: 2}, "expected": {"regions": 4, "parts": 16,
                                                                      "lines": 28, "corners": 16}}
    return B, info


# ----------------------------------------------------------------------------- faulted model


def faulted_model():
    dip = math.radians(60.0)
    cot = 1.0 / math.tan(dip)

    def xf(y, z):  # fault plane, dipping 60 deg towards +x, strike 8.5 deg off the y axis
        return 2000.0 + 0.15 * (y - 1500.0) - (z + 1500.0) * cot

    fault_normal = (1.0, -0.15, cot)  # gradient of x - xf(y, z): points into the hanging wall

    def throw(y):  # vertical throw, largest in the middle of the fault
        return 150.0 + 40.0 * math.sin(math.pi * y / LY)

    def h1(x, y):
        return (-1600.0 + 0.02 * (x - 2000.0) - 0.02 * (y - 1500.0)
                + 35.0 * math.sin(2.0 * math.pi * (0.8 * x + 0.6 * y) / 2800.0))

    def h2(x, y):
        return h1(x, y) + 335.0 + 20.0 * math.sin(2.0 * math.pi * x / 3000.0 + 1.0) * math.cos(math.pi * y / LY)

    bottom = lambda x, y: ZBOT
    top = lambda x, y: ZTOP
    fw = [bottom, h1, h2, top]
    hw = [bottom, lambda x, y: h1(x, y) - throw(y), lambda x, y: h2(x, y) - throw(y), top]
    pts = sample_points()
    for f in (fw, hw):
        check_gap("bottom/H1", f[0], f[1], 100.0, pts)
        check_gap("H1/H2", f[1], f[2], 200.0, pts)
        check_gap("H2/top", f[2], f[3], 100.0, pts)

    B = Builder()
    ny, m = 22, 13
    rows = [LY * j / ny for j in range(ny + 1)]

    def cutoff(f, y):
        z = bisect(lambda z: f(xf(y, z), y) - z, ZBOT, ZTOP)
        return xf(y, z), z

    # key vertices of each fault column, bottom to top: bottom trace, H1 hw, H1 fw, H2 hw,
    # H2 fw cut-offs, top trace
    keys = []
    for y in rows:
        pts_j = [(xf(y, ZBOT), ZBOT), cutoff(hw[1], y), cutoff(fw[1], y), cutoff(hw[2], y),
                 cutoff(fw[2], y), (xf(y, ZTOP), ZTOP)]
        for (xa, za), (xb, zb) in zip(pts_j, pts_j[1:]):
            if zb - za < 50.0:
                raise RuntimeError("fault cut-offs too close at y=%g" % y)
        keys.append([B.vertex(x, y, z) for x, z in pts_j])
    fw_key = [0, 2, 4, 5]  # key index where each footwall sheet meets the fault
    hw_key = [0, 1, 3, 5]

    def fw_xs(j, level):
        xe = B.P[keys[j][fw_key[level]]][0] / 1000.0
        return [xe * i / m for i in range(m + 1)]

    def hw_xs(j, level):
        xs = B.P[keys[j][hw_key[level]]][0] / 1000.0
        return [xs + (LX - xs) * i / m for i in range(m + 1)]

    F = [sheet(B, rows, lambda j, l=l: fw_xs(j, l), fw[l], {(m, j): keys[j][fw_key[l]] for j in range(ny + 1)})
         for l in range(4)]
    H = [sheet(B, rows, lambda j, l=l: hw_xs(j, l), hw[l], {(0, j): keys[j][hw_key[l]] for j in range(ny + 1)})
         for l in range(4)]

    FW, HW = 0, 3  # label = block * 3 + layer
    boundary = {}
    for name in ("top", "bottom", "west", "east", "south", "north"):
        boundary[name] = B.add_surface("boundary_" + name, "boundary", "model_boundary")
    B.add_part(boundary["bottom"], sheet_tris(B, F[0]), (0, 0, -1), FW + 0, OUT)
    B.add_part(boundary["bottom"], sheet_tris(B, H[0]), (0, 0, -1), HW + 0, OUT)
    B.add_part(boundary["top"], sheet_tris(B, F[3]), (0, 0, 1), FW + 2, OUT)
    B.add_part(boundary["top"], sheet_tris(B, H[3]), (0, 0, 1), HW + 2, OUT)
    for l in range(3):
        cols = [B.column(F[l][0][j], F[l + 1][0][j]) for j in range(ny + 1)]
        B.add_part(boundary["west"], B.strip(cols), (-1, 0, 0), FW + l, OUT)
        cols = [B.column(H[l][m][j], H[l + 1][m][j]) for j in range(ny + 1)]
        B.add_part(boundary["east"], B.strip(cols), (1, 0, 0), HW + l, OUT)
        for name, j, ny_dir in (("south", 0, -1), ("north", ny, 1)):
            # footwall: the last column is the fault trace from one sheet's cut-off to the next,
            # through the hanging-wall cut-offs in between
            cols = [B.column(F[l][i][j], F[l + 1][i][j]) for i in range(m)]
            cols.append(B.chain(keys[j][fw_key[l]:fw_key[l + 1] + 1]))
            B.add_part(boundary[name], B.strip(cols), (0, ny_dir, 0), FW + l, OUT)
            cols = [B.chain(keys[j][hw_key[l]:hw_key[l + 1] + 1])]
            cols += [B.column(H[l][i][j], H[l + 1][i][j]) for i in range(1, m + 1)]
            B.add_part(boundary[name], B.strip(cols), (0, ny_dir, 0), HW + l, OUT)
    for k in (1, 2):
        s = B.add_surface("H%d" % k, "horizon", "H%d" % k)
        B.add_part(s, sheet_tris(B, F[k]), (0, 0, 1), FW + k - 1, FW + k)
        B.add_part(s, sheet_tris(B, H[k]), (0, 0, 1), HW + k - 1, HW + k)
    fault = B.add_surface("F1", "fault", "F1")
    # fault patches between consecutive key curves: (footwall layer, hanging-wall layer)
    patch_layers = [(0, 0), (0, 1), (1, 1), (1, 2), (2, 2)]
    for p, (lf, lh) in enumerate(patch_layers):
        cols = [B.column(keys[j][p], keys[j][p + 1]) for j in range(ny + 1)]
        B.add_part(fault, B.strip(cols), fault_normal, FW + lf, HW + lh)
    B.surfaces = B.surfaces[6:] + B.surfaces[:6]
    info = {"n_layers": 3, "regions": {FW + l: l for l in range(3)} | {HW + l: l for l in range(3)},
            "blocks": {FW + l: 0 for l in range(3)} | {HW + l: 1 for l in range(3)},
            "expected": {"regions": 7, "parts": 31, "lines": 52, "corners": 28}}
    return B, info


MODELS = {"folded_layers": folded_model, "faulted_layers": faulted_model}


# ----------------------------------------------------------------------------- writers


def fmt_mm(v):
    s = "-" if v < 0 else ""
    v = abs(v)
    return "%s%d.%03d" % (s, v // 1000, v % 1000)


def world(B, v):
    p = B.P[v]
    return tuple(p[k] + OFFSET_MM[k] for k in range(3))


def write_ts(B, path):
    out = []
    for s in B.surfaces:
        out += ["GOCAD TSurf 1", "HEADER {", "name: %s" % s["name"], "}",
                "GOCAD_ORIGINAL_COORDINATE_SYSTEM", "NAME Default", 'AXIS_NAME "X" "Y" "Z"',
                'AXIS_UNIT "m" "m" "m"', "ZPOSITIVE Elevation", "END_ORIGINAL_COORDINATE_SYSTEM",
                "GEOLOGICAL_FEATURE %s" % s["feature"], "GEOLOGICAL_TYPE %s" % s["type"]]
        next_id = 1
        for part in s["parts"]:
            out.append("TFACE")
            local = {}
            vlines, tlines = [], []
            for t in part["tris"]:
                for v in t:
                    if v not in local:
                        local[v] = next_id
                        next_id += 1
                        x, y, z = world(B, v)
                        vlines.append("VRTX %d %s %s %s" % (local[v], fmt_mm(x), fmt_mm(y), fmt_mm(z)))
                tlines.append("TRGL %d %d %d" % tuple(local[v] for v in t))
            out += vlines + tlines
        out.append("END")
    data = ("\n".join(out) + "\n").encode("ascii")
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)
    return len(data)


def label_name(l):
    return "OUT" if l == OUT else "L%d" % l


def write_obj_twin(B, info, path):
    """OBJ + render sidecar following geogen's conventions (group <type>_<what>__A_B with A<B,
    normals from the smaller to the larger label, so box normals point inwards), for
    render.py and geogen --check."""
    side_name = {"top": "zmax", "bottom": "zmin", "west": "xmin", "east": "xmax", "south": "ymin", "north": "ymax"}
    lines, groups = [], []
    for v in range(len(B.P)):
        lines.append("v %s %s %s" % tuple(fmt_mm(c) for c in world(B, v)))
    for s in B.surfaces:
        for part in s["parts"]:
            a, b = part["labels"]
            tris = part["tris"]
            if a > b:
                a, b = b, a
                tris = [(p, r, q) for p, q, r in tris]
            what = side_name[s["name"][9:]] if s["type"] == "boundary" else s["name"]
            gtype = "box" if s["type"] == "boundary" else s["type"]
            name = "%s_%s__%s_%s" % (gtype, what, label_name(a), label_name(b))
            groups.append({"name": name, "type": gtype, "labels": [a, b], "triangles": len(tris)})
            lines.append("g " + name)
            lines += ["f %d %d %d" % (p + 1, q + 1, r + 1) for p, q, r in tris]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    side = {"box": {"min": [OFFSET_MM[0] / 1000, OFFSET_MM[1] / 1000, ZBOT],
                    "max": [OFFSET_MM[0] / 1000 + LX, OFFSET_MM[1] / 1000 + LY, ZTOP]},
            "stratigraphy": {"n_layers": info["n_layers"]},
            "regions": [{"label": l, "layer": layer} for l, layer in sorted(info["regions"].items())],
            "groups": groups}
    with open(os.path.splitext(path)[0] + ".render.json", "w") as f:
        json.dump(side, f, indent=1)


# ----------------------------------------------------------------------------- checker


def read_ts(path):
    """Triangles of a TSurf file welded by exact coordinate text: (points mm, tris, group of tri)."""
    pts, where, tris, tgroup, gnames = [], {}, [], [], []
    obj, tface, ids = None, -1, {}
    flip = False
    with open(path) as f:
        for ln, line in enumerate(f, 1):
            tok = line.split()
            if not tok:
                continue
            if tok[0] == "GOCAD":
                obj, tface, ids, flip = None, -1, {}, False
            elif tok[0] == "name:" or (tok[0] == "HEADER" and "name:" in line):
                obj = line.split("name:", 1)[1].strip().rstrip("}").strip()
            elif tok[0] == "ZPOSITIVE":
                flip = tok[1].lower() == "depth"
            elif tok[0] == "TFACE":
                tface += 1
                gnames.append("%s/%d" % (obj, tface))
            elif tok[0] in ("VRTX", "PVRTX"):
                xyz = []
                for t in tok[2:5]:
                    whole, _, frac = t.partition(".")
                    if len(frac) > 3 or "e" in t.lower():
                        raise ValueError("%s:%d: --check needs coordinates with <= 3 decimals" % (path, ln))
                    xyz.append(int(whole + frac.ljust(3, "0")) if whole not in ("", "-") else int(float(t) * 1000))
                if flip:
                    xyz[2] = -xyz[2]
                p = tuple(xyz[k] - OFFSET_MM[k] for k in range(3))
                if p not in where:
                    where[p] = len(pts)
                    pts.append(p)
                ids[int(tok[1])] = where[p]
            elif tok[0] in ("ATOM", "PATOM"):
                ids[int(tok[1])] = ids[int(tok[2])]
            elif tok[0] == "TRGL":
                if tface < 0:
                    tface = 0
                    gnames.append("%s/0" % obj)
                t = tuple(ids[int(v)] for v in tok[1:4])
                tris.append(t if not flip else (t[0], t[2], t[1]))
                tgroup.append(len(gnames) - 1)
    return pts, tris, tgroup, gnames


class UF:
    def __init__(self, n):
        self.p = list(range(n))

    def find(self, a):
        while self.p[a] != a:
            self.p[a] = self.p[self.p[a]]
            a = self.p[a]
        return a

    def union(self, a, b):
        a, b = self.find(a), self.find(b)
        if a != b:
            self.p[max(a, b)] = min(a, b)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def check_file(path, expected=None):
    """Independent checks; returns (ok, summary dict)."""
    P, T, TG, gnames = read_ts(path)
    fails = []
    res = {"file": path, "vertices": len(P), "triangles": len(T), "groups": len(gnames)}

    # triangles: repeated vertices, zero area (exact), duplicates
    seen = set()
    for t in T:
        if len(set(t)) < 3:
            fails.append("repeated vertex in triangle %r" % (t,))
            continue
        if cross(sub(P[t[1]], P[t[0]]), sub(P[t[2]], P[t[0]])) == (0, 0, 0):
            fails.append("zero-area triangle %r" % (t,))
        k = tuple(sorted(t))
        if k in seen:
            fails.append("duplicated triangle %r" % (t,))
        seen.add(k)
    # near-coincident distinct vertices (a crack that exact welding would not close): 1 cm grid
    cell = {}
    near = 0
    for i, p in enumerate(P):
        c = tuple(v // 10 for v in p)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for j in cell.get((c[0] + dx, c[1] + dy, c[2] + dz), ()):
                        if max(abs(P[j][k] - p[k]) for k in range(3)) <= 10:
                            near += 1
        cell.setdefault(c, []).append(i)
    if near:
        fails.append("%d pairs of distinct vertices closer than 1 cm" % near)

    # edges
    inc = {}
    for ti, t in enumerate(T):
        for k in range(3):
            a, b = t[k], t[(k + 1) % 3]
            inc.setdefault((min(a, b), max(a, b)), []).append(ti)
    hist = {}
    for e, ts in inc.items():
        hist[len(ts)] = hist.get(len(ts), 0) + 1
    res["edges"] = len(inc)
    res["edge_incidence"] = dict(sorted(hist.items()))
    if hist.get(1, 0):
        fails.append("%d border edges (incidence 1)" % hist[1])

    # regions: sides 2t (+, where the normal points) and 2t+1 (-), glued by radial sorting
    normals = [cross(sub(P[t[1]], P[t[0]]), sub(P[t[2]], P[t[0]])) for t in T]
    uf = UF(2 * len(T))
    for (a, b), ts in inc.items():
        d = sub(P[b], P[a])
        dd = float(dot(d, d))
        around = []
        e1 = e2 = None
        for ti in ts:
            c = [v for v in T[ti] if v != a and v != b][0]
            w = sub(P[c], P[a])
            s = dot(w, d) / dd
            u = (w[0] - s * d[0], w[1] - s * d[1], w[2] - s * d[2])
            if e1 is None:
                n1 = math.sqrt(dot(u, u))
                e1 = (u[0] / n1, u[1] / n1, u[2] / n1)
                e2 = cross(d, e1)
            ang = math.atan2(dot(u, e2), dot(u, e1))
            # does the + side of ti face increasing angle (direction d x u)?
            plus_up = dot(normals[ti], cross(d, u)) > 0
            around.append((ang, ti, plus_up))
        around.sort()
        for k in range(len(around)):
            _, t0, up0 = around[k]
            _, t1, up1 = around[(k + 1) % len(around)]
            uf.union(2 * t0 + (0 if up0 else 1), 2 * t1 + (1 if up1 else 0))
    regions = {}
    for s in range(2 * len(T)):
        regions.setdefault(uf.find(s), []).append(s)
    box_vol6 = 6
    lo = [min(p[k] for p in P) for k in range(3)]
    hi = [max(p[k] for p in P) for k in range(3)]
    for k in range(3):
        box_vol6 *= hi[k] - lo[k]
    vols, open_regions = [], 0
    for r, sides in regions.items():
        v6 = 0
        dedges = {}
        for s in sides:
            t = T[s // 2]
            det = dot(P[t[0]], cross(P[t[1]], P[t[2]]))
            # region on the - side: the normal points out of it
            v6 += det if s % 2 else -det
            oriented = t if s % 2 else (t[0], t[2], t[1])
            for k in range(3):
                a, b = oriented[k], oriented[(k + 1) % 3]
                key = (min(a, b), max(a, b))
                dedges[key] = dedges.get(key, 0) + (1 if a < b else -1)
        if any(dedges.values()):
            open_regions += 1
        vols.append(v6)
    bounded = sorted((v for v in vols if v > 0), reverse=True)
    outer = [v for v in vols if v <= 0]
    res["regions"] = len(regions)
    res["region_volumes_m3"] = [v / 6e9 for v in bounded]
    res["box_volume_m3"] = box_vol6 / 6e9
    if open_regions:
        fails.append("%d regions not closed" % open_regions)
    if len(outer) != 1 or outer[0] != -box_vol6:
        fails.append("outer region volume is not minus the bounding-box volume")
    if sum(bounded) != box_vol6:
        fails.append("bounded region volumes add up to %.6g m3, box %.6g m3" % (sum(bounded) / 6e9, box_vol6 / 6e9))

    # parts, lines, corners (meshreport's definitions)
    puf = UF(len(T))
    line_edges = []
    for e, ts in inc.items():
        if len(ts) == 2 and TG[ts[0]] == TG[ts[1]]:
            puf.union(ts[0], ts[1])
        else:
            line_edges.append(e)
    part_of = [puf.find(t) for t in range(len(T))]
    res["parts"] = len(set(part_of))
    sig = {e: tuple(sorted(set(part_of[t] for t in inc[e]))) for e in line_edges}
    at = {}
    for e in line_edges:
        for v in e:
            at.setdefault(v, []).append(e)
    corners = {v for v, es in at.items() if len(es) != 2 or sig[es[0]] != sig[es[1]]}
    res["corners"] = len(corners)
    idx = {e: i for i, e in enumerate(line_edges)}
    luf = UF(len(line_edges))
    for v, es in at.items():
        if v not in corners:
            luf.union(idx[es[0]], idx[es[1]])
    res["lines"] = len({luf.find(i) for i in range(len(line_edges))})

    if expected:
        for k, v in expected.items():
            if res[k] != v:
                fails.append("%s: %d, expected %d" % (k, res[k], v))
    res["failures"] = fails
    return not fails, res


# ----------------------------------------------------------------------------- main


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out-dir", default=os.path.normpath(os.path.join(here, "..", "models")), help="where to write the .ts files")
    ap.add_argument("--obj", metavar="DIR", help="also write <model>.obj and <model>.render.json into DIR")
    ap.add_argument("--check", nargs="*", metavar="FILE.ts",
                    help="check these TSurf files (default: the bundled models in --out-dir) and exit")
    a = ap.parse_args()

    if a.check is not None:
        files = a.check or [os.path.join(a.out_dir, n + ".ts") for n in MODELS]
        ok_all = True
        for path in files:
            name = os.path.splitext(os.path.basename(path))[0]
            expected = MODELS[name]()[1]["expected"] if (not a.check and name in MODELS) else None
            ok, res = check_file(path, expected)
            ok_all &= ok
            print("%s: %s" % (path, "PASSED" if ok else "FAILED"))
            for k in ("vertices", "triangles", "groups", "edges", "edge_incidence", "parts", "lines", "corners",
                      "regions", "region_volumes_m3", "box_volume_m3"):
                print("  %s: %s" % (k, res[k]))
            for msg in res["failures"][:20]:
                print("  FAIL: " + msg)
        return 0 if ok_all else 1

    os.makedirs(a.out_dir, exist_ok=True)
    for name, make in MODELS.items():
        B, info = make()
        path = os.path.join(a.out_dir, name + ".ts")
        size = write_ts(B, path)
        ntri = sum(len(p["tris"]) for s in B.surfaces for p in s["parts"])
        print("%s: %d vertices, %d triangles, %d bytes" % (os.path.normpath(path), len(B.P), ntri, size))
        if a.obj:
            os.makedirs(a.obj, exist_ok=True)
            write_obj_twin(B, info, os.path.join(a.obj, name + ".obj"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
