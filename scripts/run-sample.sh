#!/usr/bin/env bash
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# The main job on the bundled real sample: the skeleton (label 13) of the
# segmented frog volume -> closed triangle mesh out/frog_skeleton.ply, with its
# statistics printed and written to out/frog_skeleton.json, and a picture of it,
# out/frog_skeleton.png.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh --target isovdb_cli
mkdir -p out
build/isovdb extract data/frog/frogtissue.mhd --labels 13 -o out/frog_skeleton.ply \
  --check --stats out/frog_skeleton.json --preview out/frog_skeleton.png
