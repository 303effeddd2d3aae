// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/reservoir_extract.h"

#include "isovdb/reservoir/corner_point_grid.h"
#include "isovdb/reservoir/grdecl_reader.h"
#include "isovdb/reservoir/hex_marching_cubes.h"
#include "isovdb/reservoir/pn_tessellation.h"

#include <algorithm>
#include <set>

namespace isovdb::pipeline {

mesh::Mesh extractReservoir(const ReservoirOptions& options, Statistics& stats, Interrupter* interrupter) {
  reservoir::GrdeclDeck deck;
  reservoir::CornerPointGrid grid;
  reservoir::CornerField field;
  {
    Statistics::StageTimer timer(&stats, "read");
    const ProgressStage progress(interrupter, "read grdecl");
    progress.update(0, 1);
    deck = reservoir::readGrdecl(options.inputs, options.limits);
    progress.update(1, 1);
  }
  {
    Statistics::StageTimer timer(&stats, "grid");
    const ProgressStage progress(interrupter, "corner-point grid");
    progress.update(0, 1);
    grid = reservoir::buildCornerPointGrid(deck);
    field = reservoir::averageToCorners(grid, deck, options.property);
    progress.update(1, 1);
  }
  reservoir::HexContourResult contour;
  {
    Statistics::StageTimer timer(&stats, "marching_cubes");
    contour = reservoir::contourHexahedra(grid, field, {.iso = options.iso}, interrupter);
  }
  auto& section = stats["reservoir"];
  section["dims"] = grid.dims;
  section["cells"] = grid.cellCount();
  section["active_cells"] = grid.activeCells;
  section["usable_cells"] = std::count(field.usable.begin(), field.usable.end(), 1);
  section["inverted_cells"] = grid.invertedCells;
  section["handedness"] = grid.orientation > 0 ? "positive Jacobian" : "negative Jacobian";
  section["property"] = options.property;
  section["iso"] = options.iso;
  section["cut_cells"] = contour.cutCells;
  section["ambiguous_faces"] = contour.ambiguousFaces;
  section["mc_triangles"] = contour.mesh.triangleCount();
  section["mc_vertices"] = contour.mesh.vertexCount();
  // Faults are already in the corner-point geometry (ZCORN); their records are reported.
  std::set<std::string> faultNames;
  for (const reservoir::GrdeclFault& fault : deck.faults) faultNames.insert(fault.name);
  section["fault_records"] = deck.faults.size();
  section["faults"] = faultNames.size();
  section["property_edits_applied"] = deck.editsApplied;
  // MAPAXES is not applied: the mesh is in the deck's grid coordinates; the axes are stated.
  if (!deck.mapaxes.empty()) section["mapaxes_not_applied"] = deck.mapaxes;
  auto warnings = grid.warnings;
  warnings.insert(warnings.end(), field.warnings.begin(), field.warnings.end());
  section["warnings"] = warnings;
  if (options.maxTessellation <= 0) return std::move(contour.mesh);
  Statistics::StageTimer timer(&stats, "pn_tessellation");
  const ProgressStage progress(interrupter, "pn triangles");
  progress.update(0, 1);
  reservoir::TessellationResult pn = reservoir::tessellatePn(contour.mesh, {.maxFactor = options.maxTessellation});
  section["tessellation_max_factor"] = options.maxTessellation;
  section["tessellation_mean_edge_factor"] = pn.meanFactor;
  section["pn_triangles"] = pn.mesh.triangleCount();
  section["pn_vertices"] = pn.mesh.vertexCount();
  return std::move(pn.mesh);
}

}  // namespace isovdb::pipeline
