// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file vdb_mesher.h
/// @brief The reference contouring method: OpenVDB's own tools::volumeToMesh.
///
/// Kept as `--method vdb` so every other method can be compared with it on the
/// same field. Output in voxel index space, triangles oriented outwards (away
/// from the inside of the object), vertices shared between triangles.
#pragma once

#include "isovdb/mesh/mesh.h"
#include "isovdb/progress.h"
#include "isovdb/volume/volume.h"

namespace isovdb::contour {

struct VdbMesherOptions {
  /// Isovalue in the field's units (voxels for distance fields).
  double iso = 0.0;
  /// OpenVDB's adaptivity in [0, 1]: 0 keeps every voxel-sized quad, larger
  /// values merge flat regions (and may create self-intersections).
  double adaptivity = 0.0;
};

/// Contours a DistanceField (inside = below iso) or a Scalar volume (inside = above iso).
/// Quads are split along their shorter diagonal.
/// @throw InputError for a mask volume or an adaptivity outside [0, 1].
mesh::Mesh contourWithOpenVdb(const volume::Volume& field, const VdbMesherOptions& options = {},
                              Interrupter* interrupter = nullptr);

}  // namespace isovdb::contour
