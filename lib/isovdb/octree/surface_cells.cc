// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/surface_cells.h"

#include <algorithm>
#include <vector>

#include "isovdb/octree/morton.h"
#include "isovdb/octree/sample_phases.h"

namespace isovdb::octree {

LinearOctree surfaceCellTree(const cell::MetaCellSamples& samples, float iso) {
  const SamplePhases phases(samples, iso);
  const int size = samples.size;
  const int depth = depthForCellSize(size, 1);
  std::vector<std::uint64_t> codes;
  std::vector<std::uint8_t> signs;  // corner signs, in the order of `codes`
  forEachCrossedUnitCell(phases, {0, 0, 0}, size, [&](const std::array<int, 3>& cell, std::uint8_t config) {
    codes.push_back(zOrderCode(encodeKey(depth, cell), depth));
    signs.push_back(config);
  });
  // Z order: sort cell indices by code (codes of distinct unit cells are distinct).
  std::vector<std::uint32_t> order(codes.size());
  for (std::size_t n = 0; n < order.size(); ++n) order[n] = static_cast<std::uint32_t>(n);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return codes[a] < codes[b]; });
  std::vector<OctreeLeaf> leaves(codes.size());
  const MortonKey lead = MortonKey{1} << (3 * depth);
  for (std::size_t n = 0; n < order.size(); ++n) {
    OctreeLeaf& leaf = leaves[n];
    leaf.key = lead | codes[order[n]];
    const KeyCoord c = decodeKey(leaf.key);
    leaf.origin = c.xyz;
    leaf.size = 1;
    leaf.depth = static_cast<std::uint8_t>(depth);
    leaf.cornerSigns = signs[order[n]];
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
                              const OctreeOptions& options, OctreeBuildStats* stats, Interrupter* interrupter) {
  if (!contourReadsOnlySurfaceCells(settings, options, samples.size))
    return buildOctree(samples, settings, options, stats, interrupter);
  if (stats) *stats = OctreeBuildStats{};
  return surfaceCellTree(samples, settings.iso);
}

}  // namespace isovdb::octree
