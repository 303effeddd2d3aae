// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/stitch/edge_octree.h"

#include <cassert>

#include "isovdb/octree/morton.h"

namespace isovdb::stitch {

std::vector<int> Seam::octants() const {
  if (kind == Kind::Face) return {0, 1 << axis};
  const auto uv = octree::otherAxes(axis);
  const int u = 1 << uv[0], v = 1 << uv[1];
  return {0, u, v, u | v};
}

bool Seam::ownsEdge(const std::array<int, 3>& start, int edgeAxis, int s) const noexcept {
  if (kind == Kind::Edge) {
    if (edgeAxis != axis) return false;
    const auto uv = octree::otherAxes(axis);
    return start[uv[0]] == s && start[uv[1]] == s;
  }
  if (edgeAxis == axis || start[axis] != s) return false;
  const int w = 3 - axis - edgeAxis;  // the face's other in-plane axis
  return start[w] > 0 && start[w] < s;
}

bool Seam::touches(const std::array<int, 3>& origin, int size, int s) const noexcept {
  auto onPlane = [&](int a) { return origin[a] <= s && origin[a] + size >= s; };
  if (kind == Kind::Face) return onPlane(axis);
  const auto uv = octree::otherAxes(axis);
  return onPlane(uv[0]) && onPlane(uv[1]);
}

octree::MortonKey prefixKey(octree::MortonKey key, int octant) noexcept {
  const int depth = octree::keyDepth(key);
  const octree::MortonKey leading = octree::MortonKey{1} << (3 * depth);
  return (leading << 3) | (static_cast<octree::MortonKey>(octant) << (3 * depth)) | (key ^ leading);
}

EdgeOctree buildEdgeOctree(const Seam& seam, const std::vector<std::vector<contour::SeamCell>*>& around,
                           int metaCellSize) {
  const std::vector<int> octants = seam.octants();
  assert(around.size() == octants.size());
  const int s = metaCellSize;
  const std::array<int, 3> origin{seam.reference[0] * s, seam.reference[1] * s, seam.reference[2] * s};
  std::vector<octree::OctreeLeaf> leaves;
  std::vector<contour::SeamCell*> sources;
  for (std::size_t m = 0; m < around.size(); ++m) {
    if (!around[m]) continue;
    for (contour::SeamCell& cell : *around[m]) {
      octree::OctreeLeaf leaf;
      for (int a = 0; a < 3; ++a) leaf.origin[a] = cell.origin[a] - origin[a];
      leaf.size = cell.size;
      if (!seam.touches(leaf.origin, leaf.size, s)) continue;
      leaf.key = prefixKey(cell.key, octants[m]);
      leaf.depth = static_cast<std::uint8_t>(octree::keyDepth(leaf.key));
      leaf.cornerSigns = cell.cornerSigns;
      leaf.surface = true;
      leaves.push_back(leaf);
      sources.push_back(&cell);
    }
  }
  std::vector<octree::MortonKey> keys;
  keys.reserve(leaves.size());
  for (const auto& l : leaves) keys.push_back(l.key);
  EdgeOctree result;
  result.tree = octree::LinearOctree(2 * s, origin, std::move(leaves), /*partial=*/true);
  result.cells.assign(result.tree.leafCount(), nullptr);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::int64_t index = result.tree.findLeaf(keys[i]);
    assert(index != octree::LinearOctree::kNone);
    result.cells[static_cast<std::size_t>(index)] = sources[i];
  }
  return result;
}

}  // namespace isovdb::stitch
