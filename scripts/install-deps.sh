#!/usr/bin/env bash
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# Installs the Debian 12 packages isovdb needs (build, tests, bindings, benchmarks).
# Runs apt-get only when something is missing, so repeated runs are fast.
set -euo pipefail
packages=(
  build-essential cmake ccache pkg-config
  libopenvdb-dev libtbb-dev libeigen3-dev libglm-dev zlib1g-dev libbz2-dev libblosc-dev libboost-iostreams-dev
  libcgal-dev libgmp-dev libmpfr-dev
  libcli11-dev nlohmann-json3-dev libsegyio-dev libstb-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-numpy python3-pytest python3-openvdb python3-segyio
  python3-dev pybind11-dev python3-matplotlib python3-nbformat python3-nbclient python3-ipykernel
  python3-vtk9  # the interop tests: Mesh.to_vtk(), GLB files through VTK's glTF reader
  python3-distributed python3-zarr  # isovdb.distributed: Dask clusters, chunked volumes
)
# CI's sanitizer job (ISOVDB_SANITIZE=1): Clang with libFuzzer for fuzz/.
[ "${ISOVDB_SANITIZE:-0}" = 1 ] && packages+=(clang-14 libfuzzer-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "installing: ${missing[*]}" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
