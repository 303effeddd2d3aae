// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file reservoir_extract.h
/// @brief `isovdb reservoir`: GRDECL deck -> corner-point grid -> cell values
/// averaged to corners -> Marching Cubes on hexahedra -> loops untangled (+ optional PN
/// tessellation).
#pragma once

#include <filesystem>
#include <vector>

#include "isovdb/mesh/mesh.h"
#include "isovdb/progress.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/reservoir/grdecl_reader.h"

namespace isovdb::pipeline {

struct ReservoirOptions {
  std::vector<std::filesystem::path> inputs;  ///< grid file first, then extra property files
  std::string property;                       ///< cell property keyword (PORO, FACIES, ...)
  double iso = 0.0;
  int maxTessellation = 0;         ///< 0: flat MC triangles; K: PN triangles, factors up to K
  reservoir::GrdeclLimits limits;  ///< guards against hostile sizes in the deck
  /// Worker threads (TBB); 0 = every core. The mesh does not depend on it.
  int threads = 0;
  /// The self-intersecting pairs that remain after the loops were untangled (found by exact
  /// predicates on every run: reservoir.untangle) told apart by the cells that made them: at
  /// folded (inverted) cells, at pinch-outs, elsewhere (reservoir.self_intersecting_pairs).
  bool attributeSelfIntersections = false;
};

/// Runs the reservoir stages; figures (cells, triangles, warnings, timings) go to `stats`.
/// @throw InputError for a bad deck (naming the file).
mesh::Mesh extractReservoir(const ReservoirOptions& options, Statistics& stats, Interrupter* interrupter = nullptr);

}  // namespace isovdb::pipeline
