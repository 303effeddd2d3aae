// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file mesh_follow_ups.h
/// @brief What a command that makes a mesh may do with it afterwards, the same way in
/// each: `--check` (the validator's figures; the run exits 1 when a guarantee fails, like
/// `isovdb check`) and `--preview PNG` (a shaded picture).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "isovdb/mesh/mesh.h"
#include "isovdb/pipeline/statistics.h"

namespace isovdb::cli {

struct MeshFollowUps {
  bool check = false;
  bool noSelfIntersections = false;
  std::string previewPath;

  /// --check, --no-self-intersections and --preview on `command`.
  void addFlags(CLI::App& command);
  /// Before any work. @throw InputError when --preview does not name a .png.
  void checkPreviewPath() const;
  /// With --check: the report into stats["check"] and stats["passed"]. A mesh passes when
  /// closed (unless `openByDesign`), manifold and free of self-intersections.
  /// @return false when it fails (true without --check)
  bool checkMesh(const mesh::Mesh& mesh, bool openByDesign, pipeline::Statistics& stats) const;
  /// With --preview: the picture of `mesh` written, its path in stats["preview"].
  void drawPreview(const mesh::Mesh& mesh, pipeline::Statistics& stats) const;
};

}  // namespace isovdb::cli
