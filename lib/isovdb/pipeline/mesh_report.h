// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_report.h
/// @brief The validator's figures as statistics, and the comparison of a mesh's
///        topology with the voxel object it claims to represent.
#pragma once

#include <filesystem>

#include "isovdb/mesh/mesh.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/pipeline/load_volume.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/volume/digital_topology.h"

namespace isovdb::pipeline {

/// Validates `mesh` and returns the report as JSON (counts, closed, manifold,
/// Euler characteristic, genus per component, self-intersecting pairs).
Statistics::Json meshReportJson(const mesh::Mesh& mesh, const mesh::ValidateOptions& options = {});
Statistics::Json toJson(const mesh::MeshReport& report);

/// True when the report shows a closed, manifold mesh without self-intersections
/// (self-intersections count only when they were tested).
bool passesGuarantees(const mesh::MeshReport& report);

/// Euler characteristic of the solid a volume file describes (with the given
/// adjacency of inside voxels): dense files are streamed with the mask
/// rule of `options`; .vdb masks directly; .vdb level sets through their interior (< 0).
std::int64_t solidEulerCharacteristic(const std::filesystem::path& path, const InputOptions& options,
                                      volume::Adjacency adjacency = volume::Adjacency::Foreground26,
                                      Interrupter* interrupter = nullptr);

}  // namespace isovdb::pipeline
