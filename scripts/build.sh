#!/usr/bin/env bash
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# Configures and builds isovdb (Release) into ./build; extra arguments go to cmake --build.
# ISOVDB_BUILD_DIR and ISOVDB_BUILD_TYPE choose another folder and build type (CI's Debug
# job); ISOVDB_WERROR=1 makes warnings in isovdb's own code errors; ISOVDB_SANITIZE=1 builds
# with clang-14, AddressSanitizer + UndefinedBehaviorSanitizer and the fuzz/ harnesses
# (CI's sanitizer job; no Python module: Debian's interpreter cannot load it).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${ISOVDB_BUILD_DIR:-build}"
sanitize=()
[ "${ISOVDB_SANITIZE:-0}" = 1 ] &&
  sanitize=(-DCMAKE_CXX_COMPILER=clang++-14 -DISOVDB_SANITIZE=ON -DISOVDB_BUILD_FUZZERS=ON)
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE="${ISOVDB_BUILD_TYPE:-Release}" "${sanitize[@]}" \
  -DISOVDB_WARNINGS_AS_ERRORS="$([ "${ISOVDB_WERROR:-0}" = 1 ] && echo ON || echo OFF)" >/dev/null
cmake --build "$build_dir" -j"$(nproc)" "$@"
