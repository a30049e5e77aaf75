#!/usr/bin/env python3
"""Table-2 style figures of the remesher on structural models (a measurement, not a test).

For every MODEL:SEEDS pair: `voroseal remesh` (timed), `voroseal check` on the output, the
independent referee `meshreport --ref` for quality, fidelity and features, and optionally
`voroseal tetmesh` on the output. Prints one Markdown table (and --json for a machine copy).

  bench/remesh_table.py --voroseal build/framework/cli/voroseal \
      --meshreport ../tools-build/meshreport/meshreport \
      ../shared/models/ring/CloudSpin_fixed.ml:5000 ../shared/models/ring/CloudSpin_fixed.ml:10000
Append :SEEDS:FEATURE_ANGLE to read a soup with a feature angle (modelA6.mesh:8000:80).
"""
import argparse, json, os, subprocess, sys, tempfile, time


def run(cmd):
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p, time.time() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="+", help="MODEL:SEEDS[:FEATURE_ANGLE]")
    ap.add_argument("--voroseal", default="build/framework/cli/voroseal")
    ap.add_argument("--meshreport", default="../tools-build/meshreport/meshreport")
    ap.add_argument("--tetmesh", action="store_true", help="also tet-mesh every output")
    ap.add_argument("--out", default=None, help="keep outputs in this folder")
    ap.add_argument("--json", default=None, help="write the rows as JSON here")
    a = ap.parse_args()
    out = a.out or tempfile.mkdtemp(prefix="remesh_table_")
    os.makedirs(out, exist_ok=True)
    rows = []
    for case in a.cases:
        parts = case.split(":")
        model, seeds = parts[0], int(parts[1])
        angle = parts[2] if len(parts) > 2 else None
        stem = os.path.splitext(os.path.basename(model))[0]
        result = os.path.join(out, f"{stem}_{seeds}.ml")
        read = ["--feature-angle", angle] if angle else []
        p, seconds = run([a.voroseal, "--quiet", "remesh", model, "--seeds", str(seeds), "-o", result, "--json"] + read)
        row = {"model": stem, "seeds": seeds, "remesh_s": round(seconds, 2), "remesh_exit": p.returncode}
        if p.returncode != 0:
            row["error"] = p.stderr.strip().splitlines()[-1:] if p.stderr else ""
            rows.append(row)
            continue
        # The remesher's own verdict on the regions: same count and same adjacency, regions matched through their sides.
        try:
            topology = json.loads(p.stdout)["remesh"]["topology"]
            row["region_adjacency"] = "kept" if topology["regions_preserved"] else "changed"
            # Input features without a counterpart: all of them / those larger than the edge length.
            row["features_lost"] = f'{len(topology["features_lost"])}/{topology["features_lost_larger_than_resolution"]}'
        except (json.JSONDecodeError, KeyError):
            row["region_adjacency"] = "?"
        c, _ = run([a.voroseal, "--quiet", "check", result, "--json"])
        try:
            check = json.loads(c.stdout)
            row["check"] = "valid" if c.returncode == 0 else "invalid"
            row["check_errors"] = [x.get("name") for x in check.get("checks", []) if x.get("severity") == "error" and x.get("count", 0)]
        except json.JSONDecodeError:
            row["check"] = f"exit {c.returncode}"
        m, _ = run([a.meshreport, result, "--ref", model, "--samples", "200000"])
        rep = json.loads(m.stdout)
        q, f, s, cmp = rep["quality"], rep["features"], rep["sealing"], rep["comparison"]
        ref_f = cmp["features"]
        row.update({
            "vertices": rep["mesh"]["vertices"], "triangles": rep["mesh"]["triangles"],
            "surfaces": f"{f['surface_parts']}/{ref_f['surface_parts']['ref']}",
            "contacts": f"{f['lines']}/{ref_f['lines']['ref']}",
            "corners": f"{f['corners']}/{ref_f['corners']['ref']}",
            "regions": f"{f['regions'] - 1}/{ref_f['regions']['ref'] - 1}",
            "min_angle": round(q["min_angle"], 2), "pct_below_30": round(q["pct_angle_lt_30"], 2),
            "avg_q": round(q["q_mean"], 3), "hausdorff_pct": round(cmp["hausdorff_pct"], 3),
            "border_edges": f"{s['border_edges']}/{ref_f['border_edges']['ref']}",
            "self_intersections": s["self_intersections"],
        })
        if a.tetmesh:
            vol = os.path.join(out, f"{stem}_{seeds}.mesh")
            t, seconds = run([a.voroseal, "--quiet", "tetmesh", result, "-o", vol])
            row["tetmesh_s"] = round(seconds, 2)
            row["tetmesh_exit"] = t.returncode
            if t.returncode == 0:
                tm, _ = run([a.meshreport, vol, "--no-intersections"])
                tr = json.loads(tm.stdout).get("tetrahedra", {})
                row["tets"] = tr.get("count")
                row["min_dihedral"] = round(tr.get("min_dihedral", 0.0), 2)
                row["not_conformal"] = tr.get("surface_triangles_not_in_tets")
        rows.append(row)
        print(json.dumps(row), file=sys.stderr)
    cols = ["model", "seeds", "vertices", "triangles", "surfaces", "contacts", "corners", "regions", "region_adjacency",
            "features_lost", "min_angle",
            "pct_below_30", "avg_q", "hausdorff_pct", "border_edges", "self_intersections", "check", "remesh_s"]
    if a.tetmesh:
        cols += ["tets", "min_dihedral", "not_conformal", "tetmesh_s"]
    print("| " + " | ".join(cols) + " |")
    print("|" + "---|" * len(cols))
    for r in rows:
        print("| " + " | ".join(str(r.get(c, r.get("error", ""))) for c in cols) + " |")
    if a.json:
        with open(a.json, "w") as fh:
            json.dump(rows, fh, indent=1)


if __name__ == "__main__":
    main()
