// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file background.h
/// @brief A field's background (the value of inactive space) replaced, for meshers that
///        read it as data (OpenVDB's volumeToMesh meshes its crossings too).
#pragma once

#include "isovdb/volume/volume.h"

namespace isovdb::volume {

/// A copy of field `volume` (scalar or distance) whose background, and every inactive value
/// equal to it, is `background` (openvdb::tools::changeBackground); geometry, name and
/// metadata (the sampled box) kept. A deep copy (the grid's memory again).
/// @throw InputError when `volume` is a mask
Volume withBackground(const Volume& volume, float background);

}  // namespace isovdb::volume
