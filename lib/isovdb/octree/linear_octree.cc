// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/linear_octree.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace isovdb::octree {

LinearOctree::LinearOctree(int metaCellSize, std::array<int, 3> metaCellOrigin, std::vector<OctreeLeaf> leaves,
                           [[maybe_unused]] bool partial)
    : size_(metaCellSize),
      finestDepth_(depthForCellSize(metaCellSize, 1)),
      origin_(metaCellOrigin),
      leaves_(std::move(leaves)) {
  const int fd = finestDepth_;
  codes_.resize(leaves_.size());
  for (std::size_t i = 0; i < leaves_.size(); ++i) codes_[i] = zOrderCode(leaves_[i].key, fd);
  if (!std::is_sorted(codes_.begin(), codes_.end())) {  // the octree builder hands them in order already
    std::sort(leaves_.begin(), leaves_.end(),
              [fd](const OctreeLeaf& a, const OctreeLeaf& b) { return zOrderCode(a.key, fd) < zOrderCode(b.key, fd); });
    for (std::size_t i = 0; i < leaves_.size(); ++i) codes_[i] = zOrderCode(leaves_[i].key, fd);
  }
  // About one bucket per leaf, at most one per finest cell.
  const int codeBits = 3 * fd;
  int bucketBits = 0;
  while (bucketBits < codeBits && (std::size_t{1} << bucketBits) < leaves_.size()) ++bucketBits;
  bucketShift_ = codeBits - bucketBits;
  const std::size_t buckets = std::size_t{1} << bucketBits;
  bucketStart_.assign(buckets + 1, 0);
  std::size_t i = 0;
  for (std::size_t b = 0; b <= buckets; ++b) {
    while (i < codes_.size() && (codes_[i] >> bucketShift_) < b) ++i;
    bucketStart_[b] = static_cast<std::uint32_t>(i);
  }
#ifndef NDEBUG
  std::uint64_t volume = 0;
  for (const auto& l : leaves_) volume += std::uint64_t{1} << (3 * (fd - l.depth));
  assert(partial || leaves_.empty() || volume == (std::uint64_t{1} << (3 * fd)));
#endif
}

std::int64_t LinearOctree::findLeafContainingVoxel(std::array<int, 3> voxel) const noexcept {
  for (int a = 0; a < 3; ++a)
    if (voxel[a] < 0 || voxel[a] >= size_) return kNone;
  if (codes_.empty()) return kNone;
  const std::uint64_t code = zOrderCode(encodeKey(finestDepth_, voxel), finestDepth_);
  // Codes of earlier buckets are smaller, of later ones larger: the bound is in this bucket.
  const std::size_t bucket = code >> bucketShift_;
  const auto it =
      std::upper_bound(codes_.begin() + bucketStart_[bucket], codes_.begin() + bucketStart_[bucket + 1], code);
  if (it == codes_.begin()) return kNone;
  const std::int64_t index = (it - codes_.begin()) - 1;
  // A leaf whose min corner is this voxel contains it: no read of the leaf (a cache miss
  // per lookup where, as in regular mode, the leaves are 1-voxel cells).
  if (codes_[static_cast<std::size_t>(index)] == code) return index;
  const OctreeLeaf& l = leaves_[static_cast<std::size_t>(index)];
  for (int a = 0; a < 3; ++a)
    if (voxel[a] < l.origin[a] || voxel[a] >= l.origin[a] + l.size) return kNone;
  return index;
}

std::int64_t LinearOctree::findLeafContaining(MortonKey key) const noexcept {
  if (key == kInvalidKey) return kNone;
  const int depth = keyDepth(key);
  if (depth > finestDepth_) key = ancestorKey(key, finestDepth_);
  const std::int64_t index = findLeafContainingVoxel(cellOrigin(key));
  if (index == kNone) return kNone;
  return isAncestorOrSelf(leaves_[static_cast<std::size_t>(index)].key, key) ? index : kNone;
}

std::int64_t LinearOctree::findLeaf(MortonKey key) const noexcept {
  const std::int64_t index = findLeafContaining(key);
  return index != kNone && leaves_[static_cast<std::size_t>(index)].key == key ? index : kNone;
}

std::int64_t LinearOctree::findLeafContaining(std::array<float, 3> point) const noexcept {
  std::array<int, 3> voxel{};
  for (int a = 0; a < 3; ++a) {
    if (!(point[a] >= 0.0f && point[a] <= static_cast<float>(size_))) return kNone;
    voxel[a] = std::min(static_cast<int>(std::floor(point[a])), size_ - 1);
  }
  return findLeafContainingVoxel(voxel);
}

std::array<int, 3> LinearOctree::cellOrigin(MortonKey key) const noexcept {
  const KeyCoord c = decodeKey(key);
  const int s = size_ >> c.depth;
  return {c.xyz[0] * s, c.xyz[1] * s, c.xyz[2] * s};
}

void LinearOctree::leavesAcrossFace(std::size_t index, int face, std::vector<std::size_t>& out) const {
  out.clear();
  const OctreeLeaf& l = leaves_[index];
  const MortonKey n = faceNeighbourKey(l.key, face);
  if (n == kInvalidKey) return;
  const std::int64_t same = findLeafContaining(n);
  if (same != kNone) {
    out.push_back(static_cast<std::size_t>(same));
    return;
  }
  // The neighbour is subdivided: its leaves are a contiguous Z-order range.
  const int dn = keyDepth(n);
  const std::uint64_t lo = zOrderCode(n, finestDepth_);
  const std::uint64_t hi = lo + (std::uint64_t{1} << (3 * (finestDepth_ - dn)));
  const int axis = face >> 1;
  const int plane = (face & 1) ? l.origin[axis] + l.size : l.origin[axis];
  for (auto it = std::lower_bound(codes_.begin(), codes_.end(), lo); it != codes_.end() && *it < hi; ++it) {
    const std::size_t j = static_cast<std::size_t>(it - codes_.begin());
    const OctreeLeaf& m = leaves_[j];
    const bool touches = (face & 1) ? m.origin[axis] == plane : m.origin[axis] + m.size == plane;
    if (touches) out.push_back(j);
  }
}

std::array<std::int64_t, 4> LinearOctree::leavesAroundEdge(std::array<int, 3> start, int axis) const noexcept {
  std::array<std::int64_t, 4> result{};
  for (int q = 0; q < 4; ++q)
    result[static_cast<std::size_t>(q)] = findLeafContainingVoxel(cell::edgeQuadrantVoxel(start, axis, q));
  return result;
}

}  // namespace isovdb::octree
