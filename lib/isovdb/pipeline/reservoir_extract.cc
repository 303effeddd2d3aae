// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/reservoir_extract.h"

#include <tbb/global_control.h>

#include "isovdb/errors.h"

#include "isovdb/reservoir/corner_point_grid.h"
#include "isovdb/reservoir/grdecl_reader.h"
#include "isovdb/reservoir/hex_marching_cubes.h"
#include "isovdb/reservoir/pn_tessellation.h"
#include "isovdb/reservoir/untangle_loops.h"

#include <algorithm>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <vector>
#include <set>

namespace isovdb::pipeline {

namespace {

/// The header lines of a reservoir mesh: what was contoured, and the deck's MAPAXES (the
/// map frame a reader needs to place the grid coordinates).
std::vector<std::string> meshComments(const reservoir::GrdeclDeck& deck, const ReservoirOptions& options) {
  std::ostringstream what;
  what << std::setprecision(12) << "isovdb reservoir: " << options.property << " = " << options.iso << " of "
       << deck.path.filename().string();
  std::vector<std::string> comments{what.str()};
  if (deck.mapaxes.size() == 6) {
    std::ostringstream axes;
    axes << std::setprecision(12) << "mapaxes";
    for (const double v : deck.mapaxes) axes << ' ' << v;
    axes << " (Eclipse MAPAXES, not applied: x and y are the deck's grid coordinates; map point = P2 + x * "
            "unit(P3 - P2) + y * unit(P1 - P2) with P1, P2, P3 the three points above)";
    comments.push_back(axes.str());
  }
  return comments;
}

/// The mesh's self-intersecting pairs by the cells that made their triangles: a pair with
/// a triangle of an inverted cell counts there, else with one of a pinched cell there.
Statistics::Json attributedSelfIntersections(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs,
                                             const reservoir::HexContourResult& contour,
                                             const reservoir::CornerPointGrid& grid) {
  std::int64_t inverted = 0, pinched = 0;
  for (const auto& [a, b] : pairs) {
    const auto shape =
        static_cast<std::uint8_t>(grid.cellShape[contour.triangleCells[a]] | grid.cellShape[contour.triangleCells[b]]);
    if (shape & reservoir::CornerPointGrid::kInvertedCell)
      ++inverted;
    else if (shape & reservoir::CornerPointGrid::kPinchedCell)
      ++pinched;
  }
  const auto total = static_cast<std::int64_t>(pairs.size());
  return {{"total", total},
          {"at_inverted_cells", inverted},
          {"at_pinched_cells", pinched},
          {"elsewhere", total - inverted - pinched}};
}

}  // namespace

mesh::Mesh extractReservoir(const ReservoirOptions& options, Statistics& stats, Interrupter* interrupter) {
  if (options.threads < 0)
    throw InputError("--threads: expected 0 (every core) or more, got " + std::to_string(options.threads));
  std::optional<tbb::global_control> threads;
  if (options.threads > 0) threads.emplace(tbb::global_control::max_allowed_parallelism, options.threads);
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
    contour = reservoir::contourHexahedra(grid, field, {.iso = options.iso, .triangleCells = true}, interrupter);
  }
  reservoir::UntangleResult untangled;
  {
    Statistics::StageTimer timer(&stats, "untangle");
    const ProgressStage progress(interrupter, "untangle loops");
    progress.update(0, 1);
    untangled = reservoir::untangleLoops(contour.mesh, contour.triangleCells);
    stats["reservoir"]["untangle"] = {{"pairs_before", untangled.pairsBefore},
                                      {"pairs_after", untangled.pairsAfter},
                                      {"loops_refanned", untangled.loopsRefanned},
                                      {"skipped_too_many_pairs", untangled.skipped}};
    progress.update(1, 1);
  }
  if (options.attributeSelfIntersections)
    stats["reservoir"]["self_intersecting_pairs"] =
        attributedSelfIntersections(untangled.remainingPairs, contour, grid);
  auto& section = stats["reservoir"];
  section["dims"] = grid.dims;
  section["cells"] = grid.cellCount();
  section["active_cells"] = grid.activeCells;
  section["usable_cells"] = std::count(field.usable.begin(), field.usable.end(), 1);
  section["inverted_cells"] = grid.invertedCells;
  section["pinched_cells"] = grid.pinchedCells;
  section["handedness"] = grid.orientation > 0 ? "positive Jacobian" : "negative Jacobian";
  section["property"] = options.property;
  section["iso"] = options.iso;
  section["cut_cells"] = contour.cutCells;
  section["ambiguous_faces"] = contour.ambiguousFaces;
  section["fault_vertices_moved"] = contour.faultVertices;
  section["opposed_twin_triangles_cancelled"] = contour.cancelledTwins;
  section["face_points"] = contour.facePoints;
  section["mc_triangles"] = contour.mesh.triangleCount();
  section["mc_vertices"] = contour.mesh.vertexCount();
  // Faults are already in the corner-point geometry (ZCORN); their records are reported.
  std::set<std::string> faultNames;
  for (const reservoir::GrdeclFault& fault : deck.faults) faultNames.insert(fault.name);
  section["fault_records"] = deck.faults.size();
  section["faults"] = faultNames.size();
  section["property_edits_applied"] = deck.editsApplied;
  // MAPAXES is not applied: the mesh is in the deck's grid coordinates, as float32; map
  // coordinates (UTM northings near 6e6) would round x and y to 0.5 m and fold thin
  // parts. The axes are stated in the statistics and in the mesh file's header instead.
  if (!deck.mapaxes.empty()) section["mapaxes_not_applied"] = deck.mapaxes;
  auto warnings = grid.warnings;
  warnings.insert(warnings.end(), field.warnings.begin(), field.warnings.end());
  section["warnings"] = warnings;
  const std::vector<std::string> comments = meshComments(deck, options);
  if (options.maxTessellation <= 0) {
    contour.mesh.comments = comments;
    return std::move(contour.mesh);
  }
  Statistics::StageTimer timer(&stats, "pn_tessellation");
  const ProgressStage progress(interrupter, "pn triangles");
  progress.update(0, 1);
  reservoir::TessellationResult pn = reservoir::tessellatePn(contour.mesh, {.maxFactor = options.maxTessellation});
  section["tessellation_max_factor"] = options.maxTessellation;
  section["tessellation_mean_edge_factor"] = pn.meanFactor;
  section["tessellation_straightened"] = {
      {"pairs_before", pn.pairsBefore}, {"pairs_after", pn.pairsAfter}, {"straight_edges", pn.straightEdges}};
  section["pn_triangles"] = pn.mesh.triangleCount();
  section["pn_vertices"] = pn.mesh.vertexCount();
  pn.mesh.comments = comments;
  return std::move(pn.mesh);
}

}  // namespace isovdb::pipeline
