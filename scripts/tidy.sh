#!/usr/bin/env bash
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# Checks the naming rules of .clang-tidy over every source file of the library, the
# CLI and the bindings (clang-tidy 14, Debian's). Needs a configured build directory
# (scripts/build.sh) for its compile_commands.json. Exit status 1 on any violation.
# CI runs it after the Release tests (~6 min on 2 cores: every file is parsed with its
# OpenVDB headers).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v run-clang-tidy-14 > /dev/null; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends clang-tidy-14 >&2
fi
build="${ISOVDB_BUILD_DIR:-build}"
[ -f "$build/compile_commands.json" ] || scripts/build.sh > /dev/null
# -Wno-unknown-warning-option: the build's GCC-only warning flags.
run-clang-tidy-14 -p "$build" -quiet -j "$(nproc)" -extra-arg=-Wno-unknown-warning-option \
  "$PWD/(lib|apps|python_bindings)/.*\.cc$"
