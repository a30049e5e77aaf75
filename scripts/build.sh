#!/usr/bin/env bash
# Installs missing Debian packages (scripts/setup.sh), configures and builds voroseal in build/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
