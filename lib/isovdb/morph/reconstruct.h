// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file reconstruct.h
/// @brief A sparse slice stack → the completed stack (originals + intermediate
///        slices at every voxel plane between them) → one 3-D distance field.
///
/// Planes are spaced SliceStack::zStep apart from the first slice's height; an
/// original slice goes to the nearest plane (it moves by at most half a step when
/// its height is not a multiple of zStep) and every plane strictly between two
/// originals at heights h_a < h_b is made at fraction s = (z - h_a) / (h_b - h_a).
#pragma once

#include <vector>

#include "isovdb/morph/pair_morph.h"
#include "isovdb/morph/slice_stack.h"
#include "isovdb/progress.h"
#include "isovdb/volume/volume.h"

namespace isovdb::morph {

struct ReconstructOptions {
  PairOptions pair;
  float halfWidth = 3.f;  ///< narrow band of the output distance field, voxels (1..64)
  /// Most planes the completed stack may have: heights far apart for their z step
  /// (a typo, or a hostile heights file) would otherwise ask for one plane per step.
  int maxPlanes = 4096;
};

struct Reconstruction {
  volume::Volume volume;             ///< DistanceField, voxels, NEGATIVE inside; geometry in world units
  std::vector<Field2> planes;        ///< every plane's 2-D signed distance, bottom to top
  std::vector<double> planeHeights;  ///< world z of each plane
  std::vector<int> originalPlane;    ///< plane index of each original slice
  std::vector<PairStats> pairs;      ///< one per consecutive pair of originals
  double sdfSeconds = 0, morphSeconds = 0, assemblySeconds = 0;
};

/// @brief Fills the gaps of `stack` and assembles the volume. Pairs run in
///        parallel (TBB); the result does not depend on the thread count.
/// @throw InputError when two slices fall on the same plane (heights closer than
///        zStep), the stack is empty, the planes would exceed maxPlanes or the
///        half-width is outside 1..64; Interrupted on cancellation (checked per pair).
Reconstruction reconstruct(const SliceStack& stack, const ReconstructOptions& options,
                           Interrupter* interrupter = nullptr);

}  // namespace isovdb::morph
