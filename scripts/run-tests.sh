#!/usr/bin/env bash
# Installs what is needed, builds everything and runs every test via ctest (GoogleTest,
# pytest and the notebooks of python_bindings/).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)"
