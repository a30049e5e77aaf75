#!/usr/bin/env python3
"""How remesh + tetmesh time and memory grow with the input's triangles and the seeds.

geogen scenarios at several resolutions (input triangles), each remeshed at several seed
counts proportional to the model's area (--seeds-per-km2), then tet-meshed (`remesh
--tetmesh`). Per run: wall time and peak memory of the whole command (wait4), and the
remesh report's time per phase and memory at the end of each (resident, and peak so far). Fits time = c · triangles^a at the middle seed
density and time = c · seeds^b at the finest resolution (least squares in log-log), draws both
(PNG, matplotlib: `scripts/setup.sh --bench` installs it) and prints a Markdown table for
docs/benchmarks.md. A measurement, not a test.

  bench/scale.py --voroseal build/framework/cli/voroseal --geogen /tmp/vt/geogen/geogen \\
      --scenarios layercake,stress --res 25,50,100 --seeds-per-km2 50,100,200 --png scale.png
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

SKIP = 77


def run_measured(cmd, timeout):
    """(stdout, return code, wall seconds, peak resident MB) of one command."""
    t0 = time.time()
    with tempfile.TemporaryFile() as out:
        p = subprocess.Popen(cmd, stdout=out, stderr=subprocess.DEVNULL)
        deadline = t0 + timeout
        while True:
            pid, status, usage = os.wait4(p.pid, os.WNOHANG)
            if pid != 0:
                break
            if time.time() > deadline:
                p.kill()
                pid, status, usage = os.wait4(p.pid, 0)
                return None, -1, time.time() - t0, usage.ru_maxrss / 1024.0
            time.sleep(0.05)
        p.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        return out.read().decode(), p.returncode, time.time() - t0, usage.ru_maxrss / 1024.0


def obj_stats(path):
    """(triangles, area in km²) of an OBJ file."""
    vertices, triangles, area = [], 0, 0.0
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vertices.append(tuple(map(float, line.split()[1:4])))
            elif line.startswith("f "):
                ids = [int(t.split("/")[0]) - 1 for t in line.split()[1:]]
                a = vertices[ids[0]]
                for b, c in zip(ids[1:-1], ids[2:]):
                    b, c = vertices[b], vertices[c]
                    u = [b[k] - a[k] for k in range(3)]
                    v = [c[k] - a[k] for k in range(3)]
                    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0])
                    area += 0.5 * math.sqrt(sum(x * x for x in n))
                    triangles += 1
    return triangles, area / 1e6


def fit_exponent(xs, ys):
    """Least-squares slope of log y against log x (None with fewer than two distinct x)."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len({p[0] for p in pts}) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx


PHASES = ["optimization", "refinement", "rvd", "mesh_building", "cleanup"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--voroseal", default="build/framework/cli/voroseal")
    ap.add_argument("--geogen", required=True)
    ap.add_argument("--scenarios", default="layercake,stress")
    ap.add_argument("--res", default="25,50,100", help="geogen --res values")
    ap.add_argument("--geo-seed", type=int, default=0, help="geogen --seed")
    ap.add_argument("--seeds-per-km2", default="50,100,200",
                    help="seed densities: seeds = density x the model's surface area")
    ap.add_argument("--timeout", type=float, default=3600)
    ap.add_argument("--out", default=None, help="keep models and outputs here")
    ap.add_argument("--json", default=None, help="write the rows as JSON here")
    ap.add_argument("--png", default=None, help="draw the log-log plot here")
    ap.add_argument("remesh_args", nargs="*", help="extra remesh options (after --)")
    a = ap.parse_args()
    for binary in (a.voroseal, a.geogen):
        if not os.path.exists(binary):
            sys.stderr.write(f"scale: {binary} not found\n")
            return SKIP
    work = a.out or tempfile.mkdtemp(prefix="voroseal-scale-")
    os.makedirs(work, exist_ok=True)
    densities = [float(d) for d in a.seeds_per_km2.split(",")]
    rows = []
    for scenario in a.scenarios.split(","):
        for res in [int(r) for r in a.res.split(",")]:
            model = os.path.join(work, f"{scenario}_r{res}_s{a.geo_seed}.obj")
            if not os.path.exists(model):
                subprocess.run([a.geogen, "--scenario", scenario, "--res", str(res), "--seed",
                                str(a.geo_seed), "--quiet", "-o", model], check=True)
            triangles, area = obj_stats(model)
            for density in densities:
                seeds = max(100, int(round(density * area)))
                stem = os.path.join(work, f"{scenario}_r{res}_n{seeds}")
                cmd = [a.voroseal, "--json", "remesh", model, "--seeds", str(seeds),
                       "-o", stem + ".ml", "--tetmesh", stem + ".mesh"] + a.remesh_args
                out, code, wall, peak = run_measured(cmd, a.timeout)
                row = {"scenario": scenario, "res": res, "triangles": triangles,
                       "area_km2": round(area, 3), "seeds": seeds, "exit": code,
                       "wall_s": round(wall, 2), "peak_mb": round(peak, 1)}
                try:
                    report = json.loads(out)
                    rem, tet = report.get("remesh", {}), report.get("tetmesh", {})
                    for p in PHASES:
                        row[p + "_s"] = rem.get("timings", {}).get(p + "_s")
                        memory = rem.get("memory", {}).get(p, {})
                        row[p + "_resident_mb"] = memory.get("resident_mb")
                        row[p + "_peak_mb"] = memory.get("peak_mb")
                    row["iterations"] = rem.get("iterations")
                    row["stop_reason"] = rem.get("stop_reason")
                    row["valid"] = rem.get("valid")
                    row["tets"] = tet.get("tets")
                    row["tetmesh_s"] = tet.get("seconds", {}).get("total")
                except (TypeError, ValueError):
                    pass
                rows.append(row)
                print(json.dumps(row), file=sys.stderr, flush=True)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    print_table(rows)
    print()
    print_memory_table(rows)
    print_fits(rows, densities)
    if a.png:
        draw(rows, densities, a.png)
    return 0


def print_table(rows):
    head = ["scenario", "res", "triangles", "seeds", "wall s", "peak MB", "optim. s", "refine s",
            "build s", "clean-up s", "tetmesh s", "stop", "valid"]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        cells = [r["scenario"], r["res"], f"{r['triangles']:,}", f"{r['seeds']:,}", r["wall_s"],
                 r["peak_mb"], r.get("optimization_s"), r.get("refinement_s"),
                 r.get("mesh_building_s"), r.get("cleanup_s"), r.get("tetmesh_s"),
                 f"{r.get('stop_reason')} ({r.get('iterations')})", r.get("valid")]
        cells = [f"{c:.1f}" if isinstance(c, float) else str(c) for c in cells]
        print("| " + " | ".join(cells) + " |")


def print_memory_table(rows):
    """Per phase of the remesh: the memory it still holds at its end and the peak so far (MB);
    a phase whose peak is above the one before set it."""
    head = ["scenario", "res", "seeds"] + [p.replace("_", " ") + " (held / peak)" for p in PHASES]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for r in rows:
        cells = [r["scenario"], str(r["res"]), f"{r['seeds']:,}"]
        for p in PHASES:
            held, peak = r.get(p + "_resident_mb"), r.get(p + "_peak_mb")
            cells.append("-" if held is None else f"{held:.0f} / {peak:.0f}")
        print("| " + " | ".join(cells) + " |")


def series(rows, densities):
    """Per scenario: (triangles, wall) at the middle density, and (seeds, wall) at the finest
    resolution."""
    middle = densities[len(densities) // 2]
    out = {}
    for s in sorted({r["scenario"] for r in rows}):
        mine = [r for r in rows if r["scenario"] == s and r["exit"] == 0]
        if not mine:
            continue
        finest = max(r["res"] for r in mine)
        by_tri = sorted({r["res"]: r for r in mine
                         if abs(r["seeds"] / r["area_km2"] - middle) / middle < 0.05}.values(),
                        key=lambda r: r["triangles"])
        by_seed = sorted([r for r in mine if r["res"] == finest], key=lambda r: r["seeds"])
        out[s] = ([(r["triangles"], r["wall_s"]) for r in by_tri],
                  [(r["seeds"], r["wall_s"]) for r in by_seed])
    return out


def print_fits(rows, densities):
    print()
    for s, (tri, seed) in series(rows, densities).items():
        a = fit_exponent([t for t, _ in tri], [w for _, w in tri])
        b = fit_exponent([n for n, _ in seed], [w for _, w in seed])
        fmt = lambda e: "n/a" if e is None else f"{e:.2f}"
        print(f"- {s}: wall time ∝ triangles^{fmt(a)} (seeds ∝ area), "
              f"∝ seeds^{fmt(b)} (finest resolution)")


def draw(rows, densities, png):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write("scale: no matplotlib (scripts/setup.sh --bench installs it): no plot\n")
        return
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    for s, (tri, seed) in series(rows, densities).items():
        if tri:
            left.loglog(*zip(*tri), "o-", label=s)
        if seed:
            right.loglog(*zip(*seed), "s-", label=s)
    left.set_xlabel("input triangles")
    left.set_ylabel("remesh + tetmesh wall time (s)")
    left.set_title("seeds proportional to area")
    right.set_xlabel("seeds")
    right.set_title("finest resolution")
    for ax in (left, right):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    sys.exit(main())
