// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "mesh_follow_ups.h"

#include <filesystem>

#include "isovdb/errors.h"
#include "isovdb/io/png_file.h"
#include "isovdb/mesh/preview.h"
#include "isovdb/mesh/validate.h"
#include "isovdb/pipeline/mesh_report.h"

namespace isovdb::cli {

void MeshFollowUps::addFlags(CLI::App& command) {
  command.add_flag("--check", check, "Validate the mesh (closed, manifold, self-intersections, Euler)");
  command.add_flag("--no-self-intersections", noSelfIntersections, "With --check: skip the self-intersection test");
  command.add_option("--preview", previewPath,
                     "Draw the mesh into this .png (oblique view; outside faces bone-coloured, faces seen from "
                     "behind red)");
}

void MeshFollowUps::checkPreviewPath() const {
  if (!previewPath.empty() && std::filesystem::path(previewPath).extension() != ".png")
    throw InputError("'" + previewPath + "': --preview writes a .png");
}

bool MeshFollowUps::checkMesh(const mesh::Mesh& mesh, bool openByDesign, pipeline::Statistics& stats) const {
  if (!check) return true;
  pipeline::Statistics::StageTimer timer(&stats, "check");
  const mesh::MeshReport report = mesh::validateMesh(mesh, {.selfIntersections = !noSelfIntersections});
  stats["check"] = pipeline::toJson(report);
  const bool passed =
      pipeline::passesGuarantees(report) || (openByDesign && report.manifold && report.selfIntersectingPairs <= 0);
  stats["passed"] = passed;
  return passed;
}

void MeshFollowUps::drawPreview(const mesh::Mesh& mesh, pipeline::Statistics& stats) const {
  if (previewPath.empty()) return;
  pipeline::Statistics::StageTimer timer(&stats, "preview");
  const mesh::PreviewImage image = mesh::renderPreview(mesh);
  io::writePng(previewPath, image.width, image.height, 3, image.rgb);
  stats["preview"]["path"] = previewPath;
}

}  // namespace isovdb::cli
