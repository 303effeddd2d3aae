// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file preview.h
/// @brief A shaded picture of a mesh, to look at a run's result without a viewer.
///
/// A small software rasteriser: an oblique orthographic view of the mesh's
/// bounding box (from the front, right and above), a depth buffer, and flat
/// shading by a light at the eye. Faces seen from their front (counter-clockwise,
/// the outside of a correctly oriented mesh) are bone-coloured; faces seen from
/// behind are red, so an inside-out mesh or an open one shows at a glance.
/// Deterministic; one pass over the triangles.
#pragma once

#include <cstdint>
#include <vector>

#include "isovdb/mesh/mesh.h"

namespace isovdb::mesh {

struct PreviewOptions {
  int width = 800;   ///< pixels
  int height = 600;  ///< pixels
};

/// An RGB picture, rows from the top, 3 bytes per pixel.
struct PreviewImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
};

/// The background grey of a preview (every channel).
inline constexpr std::uint8_t kPreviewBackground = 245;

/// @brief Renders `mesh` (positions in any unit) into a width x height picture; an
///        empty mesh gives the background only.
/// @throw InputError for a size outside 16..8192 pixels.
PreviewImage renderPreview(const Mesh& mesh, const PreviewOptions& options = {});

}  // namespace isovdb::mesh
