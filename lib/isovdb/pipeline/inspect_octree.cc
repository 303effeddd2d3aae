// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/inspect_octree.h"

#include "isovdb/errors.h"
#include "isovdb/octree/inspect.h"
#include "isovdb/pipeline/extract.h"

namespace isovdb::pipeline {

void inspectOctree(const volume::Volume& input, const InspectOctreeOptions& options, Statistics& stats,
                   Interrupter* interrupter) {
  const volume::Volume field = toContourable(input, options.distance, interrupter, &stats);
  volume::MetaCellPartition partition;
  {
    Statistics::StageTimer timer(&stats, "partition");
    partition = volume::partitionMetaCells(field, options.metaCellSize, options.octree.iso);
  }
  auto& section = stats["meta_cells"];
  section["size"] = partition.size;
  section["surface_meta_cells"] = partition.cells.size();
  section["leaves_scanned"] = partition.leavesScanned;
  if (partition.cells.empty()) throw InputError("'" + input.name() + "': no meta-cell holds the surface");
  // The partition is conservative: by default take the first candidate whose
  // samples really change sign.
  cell::MetaCellSamples samples;
  volume::MetaCellIndex index = partition.cells.front();
  if (options.metaCell) {
    index = *options.metaCell;
    volume::readMetaCell(field, index, options.metaCellSize, samples);
  } else {
    for (const volume::MetaCellIndex& candidate : partition.cells) {
      index = candidate;
      volume::readMetaCell(field, index, options.metaCellSize, samples);
      if (volume::hasSignChange(samples, options.octree.iso)) break;
    }
  }
  section["inspected"] = index;
  section["inspected_has_sign_change"] = volume::hasSignChange(samples, options.octree.iso);
  octree::OctreeBuildStats buildStats;
  octree::LinearOctree tree;
  {
    Statistics::StageTimer timer(&stats, "octree");
    tree = octree::buildOctree(samples, options.octree, &buildStats, interrupter);
  }
  const octree::OctreeSummary summary = octree::summarizeOctree(tree);
  const octree::OctreeDepths depths = octree::resolveDepths(options.octree, options.metaCellSize);
  auto& out = stats["octree"];
  out["construction"] = options.octree.construction == octree::OctreeConstruction::Regular ? "regular" : "adaptive";
  out["min_level"] = depths.minDepth;
  out["max_level"] = depths.maxDepth;
  out["finest_cell_size_voxels"] = octree::cellSizeAtDepth(options.metaCellSize, depths.maxDepth);
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
