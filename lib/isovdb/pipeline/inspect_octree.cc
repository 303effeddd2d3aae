// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/inspect_octree.h"

#include <algorithm>
#include <string>

#include "isovdb/errors.h"
#include "isovdb/octree/inspect.h"
#include "isovdb/pipeline/extract.h"

namespace isovdb::pipeline {

void inspectOctree(const volume::Volume& input, const InspectOctreeOptions& options, Statistics& stats,
                   Interrupter* interrupter) {
  const ExtractOptions& extract = options.extract;
  if (extract.contour.method == ContourMethod::Vdb)
    throw InputError("--method: vdb builds no octree; expected regular or adaptive");
  const int metaCellSize = extract.metaCellSize;
  if (metaCellSize < 16 || metaCellSize > 512 || (metaCellSize & (metaCellSize - 1)) != 0)
    throw InputError("--meta-cell: expected a power of two in 16..512 (octree inspects one meta-cell), got " +
                     std::to_string(metaCellSize));
  cell::ContourSettings settings = extract.contour;
  settings.iso = isoFor(input, extract);
  settings.topology = regularTopologyFor(extract.regularTopology, input.kind());
  const volume::Volume field = toContourable(withInsideAboveIso(input, extract.scalarInside, settings.iso),
                                             extract.distance, interrupter, &stats);
  volume::MetaCellPartition partition;
  {
    Statistics::StageTimer timer(&stats, "partition");
    partition = volume::partitionMetaCells(field, metaCellSize, settings.iso);
  }
  auto& section = stats["meta_cells"];
  section["size"] = partition.size;
  section["surface_meta_cells"] = partition.cells.size();
  section["leaves_scanned"] = partition.leavesScanned;
  if (partition.cells.empty()) throw InputError("'" + input.name() + "': no meta-cell holds the surface");
  // The partition is conservative: by default take the first candidate whose
  // samples really change sign (extract skips the others).
  octree::OctreeBuildStats buildStats;
  octree::LinearOctree tree;
  if (options.metaCell) {
    // Beyond the surface's meta-cells there is nothing to inspect (and index * size would
    // overflow for indices near the int range).
    volume::MetaCellIndex lo = partition.cells.front(), hi = lo;
    for (const volume::MetaCellIndex& c : partition.cells)
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], c[a]);
        hi[a] = std::max(hi[a], c[a]);
      }
    const volume::MetaCellIndex& wanted = *options.metaCell;
    for (int a = 0; a < 3; ++a)
      if (wanted[a] < lo[a] || wanted[a] > hi[a])
        throw InputError("--index: " + std::to_string(wanted[0]) + "," + std::to_string(wanted[1]) + "," +
                         std::to_string(wanted[2]) + " lies outside the surface's meta-cells (" +
                         std::to_string(lo[0]) + ".." + std::to_string(hi[0]) + ", " + std::to_string(lo[1]) + ".." +
                         std::to_string(hi[1]) + ", " + std::to_string(lo[2]) + ".." + std::to_string(hi[2]) +
                         " at --meta-cell " + std::to_string(metaCellSize) + ")");
  }
  volume::MetaCellIndex index = options.metaCell ? *options.metaCell : partition.cells.front();
  bool crossed = false;
  {
    Statistics::StageTimer timer(&stats, "octree");
    if (options.metaCell) {
      tree = metaCellOctree(field, settings, extract.octree, metaCellSize, index, &buildStats, &crossed, interrupter);
    } else {
      for (const volume::MetaCellIndex& candidate : partition.cells) {
        index = candidate;
        buildStats = {};
        tree = metaCellOctree(field, settings, extract.octree, metaCellSize, index, &buildStats, &crossed, interrupter);
        if (crossed) break;
      }
    }
  }
  section["inspected"] = index;
  section["inspected_has_sign_change"] = crossed;
  const octree::OctreeSummary summary = octree::summarizeOctree(tree);
  const octree::OctreeDepths depths = octree::resolveDepths(extract.octree, metaCellSize);
  auto& out = stats["octree"];
  out["method"] = std::string(contourMethodName(settings.method));
  out["min_level"] = depths.minDepth;
  out["max_level"] = depths.maxDepth;
  out["finest_cell_size_voxels"] = octree::cellSizeAtDepth(metaCellSize, depths.maxDepth);
  out["leaves"] = summary.leaves;
  out["surface_leaves"] = summary.surfaceLeaves;
  out["leaves_per_level"] = summary.leavesPerDepth;
  out["surface_leaves_per_level"] = summary.surfaceLeavesPerDepth;
  out["cells_classified_per_level"] = buildStats.cellsClassified;
  out["complex_edges"] = buildStats.complexEdges;
  out["complex_faces"] = buildStats.complexFaces;
  out["complex_cells"] = buildStats.complexCells;
  out["unresolved_complex_leaves"] = buildStats.unresolvedComplexLeaves;
  out["geometric_splits"] = buildStats.geometricSplits;
  out["error_bound_splits"] = buildStats.errorBoundSplits;
  out["multi_sheet_splits"] = buildStats.multiSheetSplits;
  out["hidden_component_splits"] = buildStats.hiddenComponentSplits;
  out["balance_splits"] = buildStats.balanceSplits;
  out["balanced"] = octree::isBalanced(tree);
  if (!options.wireframe.empty()) {
    octree::writeLeafWireframe(tree, options.wireframe);
    out["wireframe"] = options.wireframe.string();
  }
}

}  // namespace isovdb::pipeline
