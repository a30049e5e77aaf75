#!/usr/bin/env bash
# Set-up, build, then the whole test suite (GoogleTest executables and Python tests via ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)" --timeout 600
