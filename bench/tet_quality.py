#!/usr/bin/env python3
"""Tet quality of remeshed models under tetmesh variants (issue 27; a measurement, not a test).

Every MODEL (RING files, and geogen models made from --scenarios x --geo-seeds at --res) is
remeshed once per --seeds count; every remesh is tet-meshed once per variant (a name and
tetmesh options, `--variant 'polish=--polish-dihedral 15'`). Read from the JSON reports: the
smallest dihedral angle, the tets under 15 deg (and their share), the tets, the TetGen time.
Prints one Markdown table per variant and the summary over all remeshes (--json: the rows).

  bench/tet_quality.py --voroseal build/framework/cli/voroseal --seeds 5000,10000 \\
      --variant 'default=' --variant 'no polish=--polish-dihedral 0' \\
      ../shared/models/ring/modelA1.ml ../shared/models/ring/CloudSpin_fixed.ml
"""
import argparse, json, os, shlex, subprocess, tempfile, time


def run(cmd, timeout):
    t0 = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, timeout
    return p, time.time() - t0


def tet_row(a, remeshed, variant_args, out):
    p, wall = run([a.voroseal, "--json", "tetmesh", remeshed, "-o", out] + variant_args, a.timeout)
    if p is None or p.returncode != 0:
        return {"error": "timeout" if p is None else p.stderr.strip().splitlines()[-1:]}
    t = json.loads(p.stdout)["tetmesh"]
    under = t["tets_below_deg"]["final"]["15"]
    return {"min_dihedral": t["min_dihedral_deg"], "tets": t["tets"], "under_15": under,
            "pct_under_15": 100.0 * under / max(t["tets"], 1),
            "tetgen_s": t["seconds"]["tetgen"], "wall_s": wall,
            "bisected_edges": t["surface_bisection"]["edges"], "polished": t.get("polished")}


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("models", nargs="*")
    ap.add_argument("--voroseal", default="build/framework/cli/voroseal")
    ap.add_argument("--geogen", default=None, help="geogen binary (for --scenarios)")
    ap.add_argument("--scenarios", default="", help="geogen scenarios, comma-separated")
    ap.add_argument("--geo-seeds", default="1", help="geogen --seed values")
    ap.add_argument("--res", default="30", help="geogen --res")
    ap.add_argument("--seeds", default="5000,10000", help="remesh seed counts")
    ap.add_argument("--remesh-args", default="", help="extra remesh options")
    ap.add_argument("--variant", action="append", default=None,
                    help="NAME=tetmesh options (repeatable; default: the defaults)")
    ap.add_argument("--timeout", type=float, default=900)
    ap.add_argument("--out", default=None, help="keep remeshes and tet meshes here")
    ap.add_argument("--json", default=None, help="write the rows as JSON here")
    a = ap.parse_args()
    out = a.out or tempfile.mkdtemp(prefix="tet_quality_")
    os.makedirs(out, exist_ok=True)
    variants = [v.split("=", 1) for v in (a.variant or ["default="])]

    models = list(a.models)
    for scenario in filter(None, a.scenarios.split(",")):
        for g in a.geo_seeds.split(","):
            path = os.path.join(out, f"{scenario}_g{g}_r{a.res}.obj")
            p, _ = run([a.geogen, "--scenario", scenario, "--res", a.res, "--seed", g, "-o", path,
                        "--quiet"],
                       a.timeout)
            if p is None or p.returncode != 0:
                print(f"tet_quality: geogen failed for {path}")
                continue
            models.append(path)

    rows = []
    for model in models:
        stem = os.path.splitext(os.path.basename(model))[0]
        for seeds in a.seeds.split(","):
            remeshed = os.path.join(out, f"{stem}_{seeds}.ml")
            p, _ = run([a.voroseal, "remesh", model, "--seeds", seeds, "-o", remeshed]
                       + shlex.split(a.remesh_args), a.timeout)
            if p is None or p.returncode != 0:
                rows.append({"model": stem, "seeds": int(seeds), "error": "remesh failed"})
                continue
            for name, args in variants:
                mesh = os.path.join(out, f"{stem}_{seeds}_{name.replace(' ', '_')}.mesh")
                row = {"model": stem, "seeds": int(seeds), "variant": name}
                row.update(tet_row(a, remeshed, shlex.split(args), mesh))
                rows.append(row)
                print(json.dumps(row), flush=True)

    for name, _ in variants:
        print(f"\n### {name}\n")
        print("| model | seeds | min dihedral | tets < 15° | tets | TetGen s |")
        print("|---|---|---|---|---|---|")
        done = [r for r in rows if r.get("variant") == name and "error" not in r]
        for r in done:
            print(f"| {r['model']} | {r['seeds']} | {r['min_dihedral']:.2f}° | {r['under_15']} "
                  f"({r['pct_under_15']:.3f} %) | {r['tets']:,} | {r['tetgen_s']:.1f} |")
        if done:
            print(f"\n{name}: {len(done)} tet meshes, min dihedral >= 12 deg in "
                  f"{sum(r['min_dihedral'] >= 12 for r in done)}, <= 0.1 % under 15 deg in "
                  f"{sum(r['pct_under_15'] <= 0.1 for r in done)}, lowest "
                  f"{min(r['min_dihedral'] for r in done):.2f} deg")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
