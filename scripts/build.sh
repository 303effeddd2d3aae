#!/usr/bin/env bash
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# Configures and builds isovdb (Release) into ./build; extra arguments go to cmake --build.
# ISOVDB_BUILD_DIR and ISOVDB_BUILD_TYPE choose another folder and build type (CI's Debug
# job); ISOVDB_WERROR=1 makes warnings in isovdb's own code errors.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${ISOVDB_BUILD_DIR:-build}"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE="${ISOVDB_BUILD_TYPE:-Release}" \
  -DISOVDB_WARNINGS_AS_ERRORS="$([ "${ISOVDB_WERROR:-0}" = 1 ] && echo ON || echo OFF)" >/dev/null
cmake --build "$build_dir" -j"$(nproc)" "$@"
