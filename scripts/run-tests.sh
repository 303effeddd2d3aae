#!/usr/bin/env bash
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# Installs what is needed, builds everything and runs every test via ctest (GoogleTest,
# pytest and the notebooks of python_bindings/).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
cd "${ISOVDB_BUILD_DIR:-build}"
ctest --output-on-failure -j"$(nproc)"
