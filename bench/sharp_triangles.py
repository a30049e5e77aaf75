#!/usr/bin/env python3
"""Where the sharp triangles of a remeshed model are, relative to its contacts and corners.

  bench/sharp_triangles.py OUT.obj [--angle 30]

Reads an OBJ (one group per surface part, welded vertices as voroseal writes them). A contact
edge is an edge not shared by exactly two triangles of one part (the model's rule: where the
set of parts changes, box edges included); a corner is a vertex with other than two contact
edges. Each triangle is classed by its vertices (at a corner; else how many lie on
contacts), and the table gives per class the triangles, the share under --angle and the mean
quality Q = 2 sqrt(3) area / (half-perimeter x longest edge). Then the contact edge lengths
against the mean edge length, and the sharp triangles with one contact edge facing a vertex
of another contact: their height and contact edge (thin strips have a small height; short
contact edges a small base). A measurement for docs/benchmarks.md, not a test.
"""
import argparse
import collections
import math
import statistics


def read_obj(path):
    """Vertices, triangles and the group (part) of each triangle."""
    vertices, triangles, groups = [], [], []
    group = 0
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append(tuple(float(x) for x in line.split()[1:4]))
            elif line.startswith(("g ", "o ")):
                group += 1
            elif line.startswith("f "):
                ids = [int(x.split("/")[0]) - 1 for x in line.split()[1:]]
                for k in range(1, len(ids) - 1):
                    triangles.append((ids[0], ids[k], ids[k + 1]))
                    groups.append(group)
    return vertices, triangles, groups


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


def angles(p):
    out = []
    for i in range(3):
        u, w = sub(p[(i + 1) % 3], p[i]), sub(p[(i + 2) % 3], p[i])
        c = (u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) / (norm(u) * norm(w) + 1e-300)
        out.append(math.degrees(math.acos(max(-1.0, min(1.0, c)))))
    return out


def quality(p):
    e = [norm(sub(p[i], p[(i + 1) % 3])) for i in range(3)]
    area = 0.5 * norm(cross(sub(p[1], p[0]), sub(p[2], p[0])))
    return 2.0 * math.sqrt(3.0) * area / (0.5 * sum(e) * max(e) + 1e-300)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("obj")
    ap.add_argument("--angle", type=float, default=30.0)
    a = ap.parse_args()
    V, F, G = read_obj(a.obj)
    parts_of = collections.defaultdict(list)  # edge -> the part of each triangle on it
    for t, g in zip(F, G):
        for i in range(3):
            parts_of[tuple(sorted((t[i], t[(i + 1) % 3])))].append(g)

    def is_contact(edge):
        parts = parts_of[edge]
        return len(parts) != 2 or parts[0] != parts[1]

    contact_edges = [e for e in parts_of if is_contact(e)]
    degree = collections.Counter()
    for u, v in contact_edges:
        degree[u] += 1
        degree[v] += 1
    on_contact = set(degree)
    corner = {v for v, d in degree.items() if d != 2}
    line_of = {}  # contact vertex -> contact line id (chains of contact edges between corners)
    adjacent = collections.defaultdict(list)
    for u, v in contact_edges:
        adjacent[u].append(v)
        adjacent[v].append(u)
    line = 0
    for start in on_contact - corner:
        if start in line_of:
            continue
        stack = [start]
        while stack:
            x = stack.pop()
            if x in line_of or x in corner:
                continue
            line_of[x] = line
            stack.extend(adjacent[x])
        line += 1
    mean_edge = statistics.mean(norm(sub(V[u], V[v])) for u, v in parts_of)

    rows = collections.defaultdict(lambda: [0, 0, 0.0])
    facing = []
    forced = 0  # sharp at a corner, between two contact edges: the input's angle there
    for t in F:
        p = [V[i] for i in t]
        key = "corner" if any(v in corner for v in t) else \
            "%d on contacts" % sum(v in on_contact for v in t)
        angle = angles(p)
        sharp = min(angle) < a.angle
        row = rows[key]
        row[0] += 1
        row[1] += sharp
        row[2] += quality(p)
        if sharp and key == "corner":
            i = angle.index(min(angle))
            forced += t[i] in corner and all(
                is_contact(tuple(sorted((t[i], t[j])))) for j in ((i + 1) % 3, (i + 2) % 3))
        if not sharp or key != "3 on contacts":
            continue
        edges = [i for i in range(3) if is_contact(tuple(sorted((t[i], t[(i + 1) % 3]))))]
        if len(edges) != 1:
            continue
        i = edges[0]
        u, v, w = t[i], t[(i + 1) % 3], t[(i + 2) % 3]
        if line_of.get(w) in (line_of.get(u), line_of.get(v)):
            continue
        base = norm(sub(V[v], V[u]))
        height = norm(cross(sub(V[v], V[u]), sub(V[w], V[u]))) / base
        facing.append((height / mean_edge, base / mean_edge))

    print(f"{a.obj}: {len(F)} triangles, mean edge {mean_edge:.4g}")
    print(f"| vertices | triangles | % under {a.angle:g} deg | mean Q |")
    print("|---|---|---|---|")
    for key in sorted(rows):
        n, s, q = rows[key]
        print(f"| {key} | {n} | {100.0 * s / n:.2f} | {q / n:.3f} |")
    print(f"sharp corner triangles whose smallest angle is between two contact edges at the "
          f"corner: {forced} of {rows['corner'][1]}")
    lengths = sorted(norm(sub(V[u], V[v])) / mean_edge for u, v in contact_edges)
    if lengths:
        short = sum(1 for x in lengths if x < 0.5)
        print(f"contact edges / mean edge: median {statistics.median(lengths):.2f}, "
              f"{100.0 * short / len(lengths):.1f} % under 0.5")
    if facing:
        print(f"sharp triangles with a contact edge facing another contact's vertex: "
              f"{len(facing)}, height / mean edge median "
              f"{statistics.median(x[0] for x in facing):.2f}, contact edge / mean edge median "
              f"{statistics.median(x[1] for x in facing):.2f}")


if __name__ == "__main__":
    main()
