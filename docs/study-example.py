# %% [markdown]
# # Resolution sweep with the voroseal Python module
#
# Remesh the two bundled models at three target edge lengths, tet-mesh each result, and compare
# the quality table (the seed paper's Table 2 columns) across resolutions. Runs as a plain script
# or cell by cell in a notebook (the `# %%` markers):
#
#     PYTHONPATH=build/python /usr/bin/python3 docs/study-example.py
#
# (build/python is where scripts/build.sh puts the module; Debian's python3 has numpy.)

# %%
import os
import tempfile

import numpy as np

import voroseal

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MODELS = [os.path.join(ROOT, "models", name) for name in ("folded_layers.ts", "faulted_layers.ts")]
EDGE_LENGTHS = [400, 200, 100]  # metres; the models are 4000 x 3000 x 1000 m
OUT = os.environ.get("VOROSEAL_EXAMPLE_OUT") or tempfile.mkdtemp(prefix="voroseal_sweep_")

# %% [markdown]
# ## Look at a model
# Everything is a numpy array or a list: vertices in file coordinates, triangles with their
# surface part, contact lines as vertex-id arrays, corners, regions as signed sides.

# %%
model = voroseal.read_model(MODELS[0])
print(model)
print("vertices", model.vertices.shape, "triangles", model.triangles.shape)
print("parts", model.part_names[:4], "...")
print("first contact runs through", len(model.contacts[0]), "vertices")
print("region 0 is bounded by", len(model.regions[0]), "sides; neighbours", model.region_adjacency[0])
lo, hi = model.bbox()
print("bbox", lo, hi)

# %% [markdown]
# ## The sweep
# A `Context` chains modules like a pipeline step list: remesh replaces the context's model,
# tetmesh adds a volume mesh, stats measures the current model (with `ref`, its distance to the
# input). Each `run` returns the module's report as a dict.

# %%
rows = []
for path in MODELS:
    name = os.path.splitext(os.path.basename(path))[0]
    model = voroseal.read_model(path)
    for h in EDGE_LENGTHS:
        ctx = voroseal.Context(model)
        row = {"model": name, "edge_length": h, "status": "ok"}
        try:
            ctx.run("remesh", edge_length=h)
            ctx.run("tetmesh", quality=1.5)
            row["tets"] = ctx.report["tetmesh"]["tets"]
            row["min_dihedral_deg"] = ctx.report["tetmesh"]["min_dihedral_deg"]
        except voroseal.Error as e:  # a failed run is reported, the sweep goes on
            row["status"] = type(e).__name__ + ": " + str(e)[:60]
        stats = ctx.run("stats", ref=path)
        for key in ("triangles", "surfaces", "contacts", "corners", "regions", "min_angle_deg",
                    "pct_triangles_angle_below_30", "avg_quality", "min_quality", "hausdorff_pct"):
            row[key] = stats.get(key)
        ctx.model.write_picture(os.path.join(OUT, f"{name}_{h}.png"), width=480, height=340)
        rows.append(row)

# %% [markdown]
# ## The table

# %%
columns = ["model", "edge_length", "triangles", "surfaces", "contacts", "corners", "regions",
           "min_angle_deg", "pct_triangles_angle_below_30", "avg_quality", "min_quality",
           "hausdorff_pct", "tets", "min_dihedral_deg", "status"]


def cell(v):
    return f"{v:.4g}" if isinstance(v, float) else str(v if v is not None else "")


print(" | ".join(columns))
for row in rows:
    print(" | ".join(cell(row.get(c)) for c in columns))

# Triangle counts should grow about 4x each time the edge length halves.
for name in sorted({r["model"] for r in rows}):
    counts = np.array([r["triangles"] for r in rows if r["model"] == name], dtype=float)
    print(name, "triangle-count ratios", np.round(counts[1:] / counts[:-1], 2))
print("pictures in", OUT)

# %% [markdown]
# ## The same study from a study file
# `voroseal run examples/studies/resolution_sweep.json` does all of the above from the command
# line and also writes summary.csv, summary.json and an HTML report; from Python:
#
#     summary = voroseal.run_study(os.path.join(ROOT, "examples/studies/resolution_sweep.json"),
#                                  output=os.path.join(OUT, "study"))
#     print(summary["runs_ok"], "of", summary["runs_total"], "runs ok")
