// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/surface_cells.h"

#include <algorithm>
#include <vector>

#include "isovdb/octree/morton.h"
#include "isovdb/octree/sample_phases.h"

namespace isovdb::octree {

LinearOctree surfaceCellTree(const cell::MetaCellSamples& samples, float iso) {
  return surfaceCellTree(samples, SamplePhases(samples, iso));
}

LinearOctree surfaceCellTree(const cell::MetaCellSamples& samples, const SamplePhases& phases) {
  const int size = samples.size;
  const int depth = depthForCellSize(size, 1);
  // Each cell as its Z-order code (at most 27 bits) above its corner signs: codes of
  // distinct unit cells are distinct, so sorting these plain integers is Z order (an index
  // sort comparing codes through the index was a tenth of regular mode's tree).
  std::vector<std::uint64_t> cells;
  forEachCrossedUnitCell(phases, {0, 0, 0}, size, [&](const std::array<int, 3>& cell, std::uint8_t config) {
    cells.push_back((zOrderCode(encodeKey(depth, cell), depth) << 8) | config);
  });
  std::sort(cells.begin(), cells.end());
  std::vector<OctreeLeaf> leaves(cells.size());
  const MortonKey lead = MortonKey{1} << (3 * depth);
  for (std::size_t n = 0; n < cells.size(); ++n) {
    OctreeLeaf& leaf = leaves[n];
    leaf.key = lead | (cells[n] >> 8);
    const KeyCoord c = decodeKey(leaf.key);
    leaf.origin = c.xyz;
    leaf.size = 1;
    leaf.depth = static_cast<std::uint8_t>(depth);
    leaf.cornerSigns = static_cast<std::uint8_t>(cells[n] & 0xffu);
    leaf.surface = true;
  }
  return LinearOctree(size, samples.origin, std::move(leaves), /*partial=*/true);
}

bool contourReadsOnlySurfaceCells(const cell::ContourSettings& settings, const OctreeOptions& options,
                                  int metaCellSize) {
  return settings.method == cell::ContourMethod::Regular && options.detectInteriorComponents &&
         resolveDepths(options, metaCellSize).maxDepth == depthForCellSize(metaCellSize, 1);
}

LinearOctree buildContourTree(const cell::MetaCellSamples& samples, const cell::ContourSettings& settings,
                              const OctreeOptions& options, OctreeBuildStats* stats, Interrupter* interrupter,
                              const UnitEdgeCrossings* crossings, const SamplePhases* phases, BuildMemo* memo) {
  if (!contourReadsOnlySurfaceCells(settings, options, samples.size))
    return buildOctree(samples, settings, options, stats, interrupter, crossings, phases, memo);
  if (stats) *stats = OctreeBuildStats{};
  return phases ? surfaceCellTree(samples, *phases) : surfaceCellTree(samples, settings.iso);
}

}  // namespace isovdb::octree
