#!/usr/bin/env python3
"""`remesh --distance-bound` against uniform remeshes (issue 26; a measurement, not a test).

For every MODEL: uniform remeshes at each of --uniform seed counts, and one remesh with
--distance-bound BOUND over --seeds (the coarsest size). Every output is measured by the
independent referee `meshreport --ref MODEL` (two-sided Hausdorff distance, triangles, quality).
Prints one Markdown table (and --json for a machine copy): which runs meet the bound, and with
how many triangles.

  bench/distance_bound.py --voroseal build/framework/cli/voroseal \\
      --meshreport ../tools-build/meshreport/meshreport --bound 0.1% --seeds 2000 \\
      --uniform 2000,8000,32000 ../shared/models/scec/*.ts ../shared/models/ring/CloudSpin_fixed.ml
"""
import argparse, json, os, subprocess, tempfile, time


def run(cmd):
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p, time.time() - t0


def measure(meshreport, output, model):
    p, _ = run([meshreport, output, "--ref", model])
    r = json.loads(p.stdout)
    q = r.get("quality", {})
    return {"hausdorff": r["comparison"]["hausdorff"],
            "hausdorff_pct": r["comparison"]["hausdorff_pct"],
            "triangles": r["comparison"]["features"]["triangles"]["model"],
            "q_mean": q.get("q_mean"), "pct_under_30": q.get("pct_angle_lt_30")}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("models", nargs="+")
    ap.add_argument("--voroseal", default="build/framework/cli/voroseal")
    ap.add_argument("--meshreport", default="../tools-build/meshreport/meshreport")
    ap.add_argument("--bound", default="0.1%", help="--distance-bound (a length or N%%)")
    ap.add_argument("--seeds", type=int, default=2000, help="seeds of the bounded remesh")
    ap.add_argument("--uniform", default="2000,8000,32000", help="seed counts of the uniform remeshes")
    ap.add_argument("--out", default=None, help="keep outputs in this folder")
    ap.add_argument("--json", default=None, help="write the rows as JSON here")
    a = ap.parse_args()
    out = a.out or tempfile.mkdtemp(prefix="distance_bound_")
    os.makedirs(out, exist_ok=True)
    rows = []
    for model in a.models:
        stem = os.path.splitext(os.path.basename(model))[0]
        runs = [(f"uniform {n}", ["--seeds", str(n)]) for n in map(int, a.uniform.split(","))]
        runs.append((f"bound {a.bound} over {a.seeds}",
                     ["--seeds", str(a.seeds), "--distance-bound", a.bound]))
        bound = None
        for name, args in runs:
            result = os.path.join(out, f"{stem}_{name.replace(' ', '_').replace('%', 'pc')}.obj")
            p, seconds = run([a.voroseal, "--quiet", "--json", "remesh", model, "-o", result] + args)
            row = {"model": stem, "run": name, "exit": p.returncode, "seconds": round(seconds, 1)}
            try:
                report = json.loads(p.stdout)["remesh"]
                row["seeds"] = report["seeds"]
                if "distance_bound" in report:
                    bound = report["distance_bound"]["bound"]
                    row["rounds"] = len(report["distance_bound"]["rounds"])
            except (json.JSONDecodeError, KeyError):
                pass
            if os.path.exists(result):
                row.update(measure(a.meshreport, result, model))
            rows.append(row)
        for row in rows:
            if row["model"] == stem and bound is not None and "hausdorff" in row:
                row["meets_bound"] = row["hausdorff"] <= bound
    print(f"| model | run | seeds | triangles | Hausdorff (% diag) | meets {a.bound} | Q mean | s |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['model']} | {r['run']} | {r.get('seeds', '-')} | {r.get('triangles', '-')} | "
              f"{r.get('hausdorff', float('nan')):.4g} ({r.get('hausdorff_pct', float('nan')):.3f}) | "
              f"{'yes' if r.get('meets_bound') else 'no'} | {r.get('q_mean') or float('nan'):.3f} | "
              f"{r['seconds']} |")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
