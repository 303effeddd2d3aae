// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file sampled_box.h
/// @brief The index box a volume's file sampled (its dims), kept with the grid.
///
/// Sparse grids forget where the data ended: inactive space inside the file and
/// outside it look alike. Ingest records the sampled box in the grid's metadata
/// (`isovdb_sampled_min`, `isovdb_sampled_max`, index space, inclusive), so it
/// travels with the grid into `.vdb` files and back, and the pipeline can treat
/// surfaces that reach the data boundary (pipeline/data_boundary.h).
#pragma once

#include <array>
#include <optional>

#include "isovdb/volume/volume.h"

namespace isovdb::volume {

/// Inclusive box of voxel indices.
struct IndexBox {
  std::array<int, 3> min{0, 0, 0};
  std::array<int, 3> max{-1, -1, -1};
};

/// Records `box` as the volume's sampled box (in the grid's metadata).
/// @pre volume.valid()
void setSampledBox(const Volume& volume, const IndexBox& box);

/// The sampled box recorded by ingest (or read back from a `.vdb` file written by
/// isovdb); std::nullopt when the grid carries none.
std::optional<IndexBox> sampledBox(const Volume& volume);

}  // namespace isovdb::volume
