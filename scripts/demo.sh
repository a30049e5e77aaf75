#!/usr/bin/env bash
# Set-up, build, then the main job on a bundled model: validity check, remesh at a 150 m target
# edge length, tet mesh of the result, and the quality tables (input; remeshed, with the
# Hausdorff distance to the input; volume mesh). Outputs go to out/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
model=${1:-models/faulted_layers.ts}
edge=${2:-150}
out=out/demo
mkdir -p "$out"
stem=$(basename "${model%.*}")
vs=${VOROSEAL:-build/framework/cli/voroseal}
echo "== check: $model"
"$vs" check "$model" | tail -n 1
echo "== remesh + tetmesh (edge length $edge)"
"$vs" remesh "$model" --edge-length "$edge" -o "$out/$stem.remeshed.ml" --tetmesh "$out/$stem.mesh"
echo "== quality of the input"
"$vs" --quiet stats "$model"
echo "== quality of the remeshed surfaces (Hausdorff distance to the input)"
"$vs" --quiet stats "$out/$stem.remeshed.ml" --ref "$model"
echo "== volume mesh"
"$vs" --quiet stats "$out/$stem.mesh"
echo "outputs: $out/$stem.remeshed.ml (surfaces), $out/$stem.mesh (tetrahedra, Medit)"
