#!/usr/bin/env python3
"""Robustness sweep of the remesher on models built the way implicit modellers build them.

geogen scenarios x random geogen seeds x resolutions (seed counts) -> `voroseal remesh` ->
`voroseal check` on the output -> the independent referee `meshreport --ref`. A run passes
when:
  - remesh exits 0 and `check` says the output is valid;
  - the referee finds no self-intersecting pair and no border edge (the inputs are sealed);
  - no region is gained, and every region lost is one the remesh report names as merged;
  - with --keep-topology, the referee counts the input's surface parts, contacts, corners and
    regions in the output.
Prints one Markdown table of pass rates and quality per scenario (and --json for the rows).
This is a measurement, not a test; `--quick` is the slice that ctest runs.

  bench/robustness.py --voroseal build/framework/cli/voroseal \
      --scenarios normal_fault,graben --geo-seeds 1,2,3 --res 30,40 --seeds 2000,8000,15000

geogen and meshreport are taken from --geogen / --meshreport, or built from ../shared/tools
into --tools-dir when absent. Exit 0 when every run passes (or --min-pass of them), 1
otherwise, 77 when the tools cannot be found (ctest reads 77 as skipped).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SHARED_TOOLS = os.path.normpath(os.path.join(HERE, "..", "..", "shared", "tools"))
SCENARIOS = ["layercake", "normal_fault", "fault_network", "graben", "thin_layers"]
SKIP = 77


def run(cmd, timeout=None):
    t0 = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, time.time() - t0
    return p, time.time() - t0


def tool(path, name, tools_dir):
    """The tool's binary: the given path, or built from ../shared/tools/NAME into tools_dir."""
    if path:
        return path if os.path.exists(path) else None
    binary = os.path.join(tools_dir, name, name)
    if os.path.exists(binary):
        return binary
    source = os.path.join(SHARED_TOOLS, name)
    if not os.path.isdir(source):
        return None
    build = os.path.join(tools_dir, name)
    for cmd in (["cmake", "-S", source, "-B", build, "-DCMAKE_BUILD_TYPE=Release"],
                ["cmake", "--build", build, "-j2"]):
        p, _ = run(cmd)
        if p is None or p.returncode != 0:
            sys.stderr.write(f"robustness: cannot build {name}:\n{p.stdout if p else ''}\n")
            return None
    return binary if os.path.exists(binary) else None


def get(d, path, default=None):
    for key in path.split("."):
        if not isinstance(d, dict) or key not in d:
            return default
        d = d[key]
    return d


def one_run(a, model, scenario, geo_seed, res, seeds, out_dir):
    stem = f"{scenario}_r{res}_s{geo_seed}_n{seeds}"
    out = os.path.join(out_dir, stem + ".obj")
    report = os.path.join(out_dir, stem + ".json")
    cmd = [a.voroseal, "--quiet", "--json", "remesh", model, "-o", out, "--seeds", str(seeds)
           ] + a.remesh_args
    p, seconds = run(cmd, timeout=a.timeout)
    row = {"scenario": scenario, "geo_seed": geo_seed, "res": res, "seeds": seeds,
           "seconds": round(seconds, 2), "exit": None if p is None else p.returncode,
           "reasons": []}
    if p is None:
        row["reasons"].append("timeout")
        return row
    if p.returncode != 0:
        row["reasons"].append(f"remesh exit {p.returncode}")
    try:
        rep = json.loads(p.stdout)
    except json.JSONDecodeError:
        rep = {}
    with open(report, "w") as f:
        json.dump(rep, f, indent=1)
    rep = rep.get("remesh", rep)
    if not os.path.exists(out):
        row["reasons"].append("no output")
        return row
    c, _ = run([a.voroseal, "--quiet", "check", out])
    row["check"] = c.returncode if c else None
    if c is None or c.returncode != 0:
        row["reasons"].append("check: invalid")
    m, _ = run([a.meshreport, out, "--ref", model, "--samples", "50000"])
    if m is None or m.returncode != 0:
        row["reasons"].append("referee failed")
        return row
    mr = json.loads(m.stdout)
    crossings = get(mr, "sealing.self_intersections", -1)
    borders = get(mr, "sealing.border_edges", -1)
    regions_out = get(mr, "features.regions", -1)
    regions_in = get(mr, "comparison.features.regions.ref", -1)
    row.update({
        "crossings": crossings, "borders": borders,
        "regions_in": regions_in, "regions_out": regions_out,
        "q_mean": get(mr, "quality.q_mean"),
        "under30": get(mr, "quality.pct_angle_lt_30"),
        "min_angle": get(mr, "quality.min_angle"),
        "hausdorff_pct": get(mr, "comparison.hausdorff_pct"),
        "seeds_added": get(rep, "refinement.seeds_added", 0)
        + get(rep, "repair_refinement.seeds_added", 0),
    })
    if crossings != 0:
        row["reasons"].append(f"{crossings} crossing pairs")
    if borders != 0:
        row["reasons"].append(f"{borders} border edges")
    if a.keep_topology:
        # Every input feature kept: the referee's counts of the output equal the input's.
        for key in ("surface_parts", "lines", "corners", "regions"):
            model_n = get(mr, f"comparison.features.{key}.model", -1)
            ref_n = get(mr, f"comparison.features.{key}.ref", -2)
            if model_n != ref_n:
                row["reasons"].append(f"{key} {ref_n} -> {model_n}")
    merged = len(get(rep, "topology.regions_lost", []) or [])
    if regions_in >= 0 and regions_out > regions_in:
        row["reasons"].append(f"{regions_out - regions_in} regions gained")
    if regions_in >= 0 and regions_out < regions_in and regions_in - regions_out > merged:
        row["reasons"].append(f"{regions_in - regions_out - merged} regions lost unreported")
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--voroseal", default="build/framework/cli/voroseal")
    ap.add_argument("--geogen", default=None)
    ap.add_argument("--meshreport", default=None)
    ap.add_argument("--tools-dir", default=os.path.join(tempfile.gettempdir(), "voroseal-tools"))
    ap.add_argument("--scenarios", default=",".join(SCENARIOS))
    ap.add_argument("--geo-seeds", default="1,2,3", help="geogen --seed values")
    ap.add_argument("--res", default="30", help="geogen --res values")
    ap.add_argument("--seeds", default="3000,8000", help="remesh seed counts")
    ap.add_argument("--quick", action="store_true",
                    help="the ctest slice: res 20, geogen seeds 1-3, 2000 seeds")
    ap.add_argument("--keep-topology", action="store_true",
                    help="remesh with --keep-topology; a run passes only when the referee counts "
                    "as many surface parts, contacts (lines), corners and regions as in the input")
    ap.add_argument("--timeout", type=float, default=600)
    ap.add_argument("--min-pass", type=int, default=None,
                    help="exit 0 when at least this many runs pass (default: all of them)")
    ap.add_argument("--out", default=None, help="keep models and outputs here")
    ap.add_argument("--json", default=None, help="write the rows as JSON here")
    ap.add_argument("remesh_args", nargs="*", help="extra remesh options (after --)")
    a = ap.parse_args()
    if a.keep_topology:
        a.remesh_args = ["--keep-topology"] + a.remesh_args
    if a.quick:
        a.res, a.geo_seeds, a.seeds = "20", "1,2,3", "2000"
    if not os.path.exists(a.voroseal):
        sys.stderr.write(f"robustness: no voroseal at {a.voroseal}\n")
        return SKIP
    a.geogen = tool(a.geogen, "geogen", a.tools_dir)
    a.meshreport = tool(a.meshreport, "meshreport", a.tools_dir)
    if not a.geogen or not a.meshreport:
        sys.stderr.write("robustness: geogen or meshreport not found (../shared/tools); skipped\n")
        return SKIP
    out_dir = a.out or tempfile.mkdtemp(prefix="robustness_")
    os.makedirs(out_dir, exist_ok=True)
    rows = []
    for scenario in a.scenarios.split(","):
        for res in [int(r) for r in a.res.split(",")]:
            for geo_seed in [int(s) for s in a.geo_seeds.split(",")]:
                model = os.path.join(out_dir, f"{scenario}_r{res}_s{geo_seed}.obj")
                if not os.path.exists(model):
                    g, _ = run([a.geogen, "--scenario", scenario, "--res", str(res), "--seed",
                                str(geo_seed), "-o", model, "--quiet"])
                    if g is None or g.returncode != 0:
                        sys.stderr.write(f"robustness: geogen failed for {model}\n")
                        return 1
                for seeds in [int(n) for n in a.seeds.split(",")]:
                    row = one_run(a, model, scenario, geo_seed, res, seeds, out_dir)
                    row["pass"] = not row["reasons"]
                    rows.append(row)
                    print(f"{'PASS' if row['pass'] else 'FAIL'} {scenario} res {res} seed "
                          f"{geo_seed} {seeds} seeds ({row['seconds']} s)"
                          + ("" if row["pass"] else ": " + ", ".join(row["reasons"])),
                          flush=True)
    print()
    print("| scenario | runs | pass | mean Q | % < 30 deg | min angle | Hausdorff % | seeds added "
          "| s/run |")
    print("|---|---|---|---|---|---|---|---|---|")

    def mean(xs):
        xs = [x for x in xs if isinstance(x, (int, float))]
        return sum(xs) / len(xs) if xs else float("nan")

    def smallest(xs):
        xs = [x for x in xs if isinstance(x, (int, float))]
        return min(xs) if xs else float("nan")
    for scenario in a.scenarios.split(",") + ["all"]:
        rs = [r for r in rows if scenario in ("all", r["scenario"])]
        if not rs:
            continue
        print(f"| {scenario} | {len(rs)} | {sum(r['pass'] for r in rs)} | "
              f"{mean(r.get('q_mean') for r in rs):.3f} | {mean(r.get('under30') for r in rs):.2f} | "
              f"{smallest(r.get('min_angle') for r in rs):.3g} | "
              f"{mean(r.get('hausdorff_pct') for r in rs):.3f} | "
              f"{mean(r.get('seeds_added') for r in rs):.0f} | {mean(r['seconds'] for r in rs):.1f} |")
    passed = sum(r["pass"] for r in rows)
    print(f"\nrobustness: {passed} passed, {len(rows) - passed} failed")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    floor = len(rows) if a.min_pass is None else a.min_pass
    return 0 if passed >= floor else 1


if __name__ == "__main__":
    sys.exit(main())
