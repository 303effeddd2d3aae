// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/surface_cells.h"

#include <algorithm>
#include <bit>
#include <vector>

#include "isovdb/octree/morton.h"
#include "isovdb/octree/sample_phases.h"

namespace isovdb::octree {

LinearOctree surfaceCellTree(const cell::MetaCellSamples& samples, float iso) {
  const SamplePhases phases(samples, iso);
  const int size = samples.size;
  const int depth = depthForCellSize(size, 1);
  // Cells i0 .. i0 + 62 of a row come from one 64-bit run of each of the four sample
  // rows at their corners: bit i of `all` (`any`) is set iff every (some) corner
  // sample at x = i0 + i is inside; a cell is crossed iff it has an inside corner but
  // not only inside corners.
  constexpr int kCellsPerRun = 63;
  std::vector<std::uint64_t> codes;
  std::vector<std::uint8_t> signs;  // corner signs, in the order of `codes`
  for (int k = 0; k < size; ++k)
    for (int j = 0; j < size; ++j)
      for (int i0 = 0; i0 < size; i0 += kCellsPerRun) {
        const int cells = std::min(kCellsPerRun, size - i0);
        const std::array<std::uint64_t, 4> rows{phases.row(i0, j, k, cells + 1), phases.row(i0, j + 1, k, cells + 1),
                                                phases.row(i0, j, k + 1, cells + 1),
                                                phases.row(i0, j + 1, k + 1, cells + 1)};
        const std::uint64_t all = rows[0] & rows[1] & rows[2] & rows[3];
        const std::uint64_t any = rows[0] | rows[1] | rows[2] | rows[3];
        std::uint64_t crossed = (any | (any >> 1)) & ~(all & (all >> 1)) & SamplePhases::lowBits(cells);
        while (crossed != 0) {
          const int i = std::countr_zero(crossed);
          crossed &= crossed - 1;
          std::uint8_t config = 0;
          for (int c = 0; c < 8; ++c) {
            const std::uint64_t row = rows[static_cast<std::size_t>(c >> 1)];  // (y, z) bits of the corner
            config = static_cast<std::uint8_t>(config | (((row >> (i + (c & 1))) & 1u) << c));
          }
          codes.push_back(zOrderCode(encodeKey(depth, {i0 + i, j, k}), depth));
          signs.push_back(config);
        }
      }
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
