#!/usr/bin/env bash
# Set-up, build, then the main job on a bundled model: validity check, remesh, tet mesh, and the
# quality table of the input and the result.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
model=${1:-models/faulted_layers.ts}
out=out/demo
mkdir -p "$out"
vs=build/framework/cli/voroseal
"$vs" check "$model"
"$vs" stats "$model"
