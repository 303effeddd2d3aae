// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/meta_cells.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "isovdb/volume/grids.h"

namespace isovdb::volume {

namespace {

int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

bool isPowerOfTwo(int v) { return v > 0 && (v & (v - 1)) == 0; }

using FieldLeaf = FieldGrid::TreeType::LeafNodeType;

/// The side of the isovalue a scalar field's sample reads as when its meta-cell is
/// contoured: inside at or above the isovalue, and outside beyond the caps box
/// (pipeline/octree_contour.cc sets those samples far outside).
class ScalarSides {
 public:
  ScalarSides(float iso, const std::optional<IndexBox>& box) : iso_(iso), box_(box) {}

  bool inside(const openvdb::Coord& c, float value) const { return inBox(c) && value >= iso_; }
  bool inside(float value) const { return value >= iso_; }
  /// True if every sample of [lo, hi] is in the box: their sides need no coordinates.
  bool boxHolds(const openvdb::Coord& lo, const openvdb::Coord& hi) const { return !box_ || (inBox(lo) && inBox(hi)); }

 private:
  bool inBox(const openvdb::Coord& c) const {
    if (!box_) return true;
    for (int a = 0; a < 3; ++a)
      if (c[a] < box_->min[a] || c[a] > box_->max[a]) return false;
    return true;
  }
  float iso_;
  std::optional<IndexBox> box_;
};

/// Whether a scalar field's leaf can hold or border a crossing: its samples read on both
/// sides, or a sample next to one of its faces (in the neighbouring leaf, tile or
/// background, as readBlock reads them) reads on the other side than the leaf's. A
/// leaf on one side among samples on that side gives no meta-cell a sign change.
/// `insideAt(coord, value)` is the side of a sample; sides are counted, not branched on,
/// so the loops vectorise where it ignores the coordinate.
template <typename InsideAt>
bool leafNearIso(const FieldLeaf& leaf, const FieldGrid::ConstAccessor& accessor, const InsideAt& insideAt) {
  constexpr int kDim = static_cast<int>(FieldLeaf::DIM);
  const openvdb::Coord origin = leaf.origin();
  const float* values = leaf.buffer().data();
  openvdb::Index insideCount = 0;
  for (openvdb::Index i = 0; i < FieldLeaf::SIZE; ++i)
    insideCount += insideAt(leaf.offsetToGlobalCoord(i), values[i]) ? 1 : 0;
  if (insideCount != 0 && insideCount != FieldLeaf::SIZE) return true;
  const int sideCount = insideCount != 0 ? kDim * kDim : 0;  // a face layer all on the leaf's side
  for (int a = 0; a < 3; ++a)
    for (const int direction : {-1, 1}) {
      openvdb::Coord neighbour = origin;
      neighbour[a] += direction * kDim;
      const FieldLeaf* next = accessor.probeConstLeaf(neighbour);
      const float* data = next ? next->buffer().data() : nullptr;
      const float tile = next ? 0.0f : accessor.getValue(neighbour);
      // The neighbour's layer of samples against this leaf's face (its local coordinate on axis a).
      const int u = (a + 1) % 3, w = (a + 2) % 3;
      openvdb::Coord local;
      local[a] = direction > 0 ? 0 : kDim - 1;
      int layerInside = 0;
      for (local[u] = 0; local[u] < kDim; ++local[u])
        for (local[w] = 0; local[w] < kDim; ++local[w]) {
          const float value = data ? data[FieldLeaf::coordToOffset(local)] : tile;
          layerInside += insideAt(neighbour + local, value) ? 1 : 0;
        }
      if (layerInside != sideCount) return true;
    }
  return false;
}

/// leafNearIso with the sides of `sides`: without coordinates where the leaf and the
/// samples next to it lie in the box (all but the leaves along its faces).
bool scalarLeafNearIso(const FieldLeaf& leaf, const FieldGrid::ConstAccessor& accessor, const ScalarSides& sides) {
  const openvdb::Coord origin = leaf.origin();
  if (sides.boxHolds(origin.offsetBy(-1), origin.offsetBy(static_cast<int>(FieldLeaf::DIM))))
    return leafNearIso(leaf, accessor, [&](const openvdb::Coord&, float value) { return sides.inside(value); });
  return leafNearIso(leaf, accessor, [&](const openvdb::Coord& c, float value) { return sides.inside(c, value); });
}

}  // namespace

bool backgroundInside(const Volume& field, float iso) {
  const float background = fieldGrid(field).background();
  return field.kind() == VolumeKind::Scalar ? background >= iso : background <= iso;
}

MetaCellPartition partitionMetaCells(const Volume& field, int size, float iso, const std::optional<IndexBox>& capsBox) {
  const FieldGrid& grid = fieldGrid(field);
  if (!isPowerOfTwo(size) || size < 8 || size > 4096)
    throw InputError("meta-cell size " + std::to_string(size) + " must be a power of two in 8..4096");
  MetaCellPartition partition;
  partition.size = size;
  // Leaf indices can repeat across leaves: collect in an ordered set (z, y, x).
  std::set<std::array<int, 3>> cells;
  // The box's samples, grown by one for crossings with their neighbours, belong
  // to every meta-cell whose closed range [i*S, i*S+S] they touch.
  auto addBox = [&](openvdb::CoordBBox box) {
    box.expand(1);
    std::array<int, 3> lo, hi;
    for (int a = 0; a < 3; ++a) {
      lo[a] = floorDiv(box.min()[a] - 1, size);
      hi[a] = floorDiv(box.max()[a], size);
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          // Meta-cell i covers samples [i*S, i*S+S]: keep it only if the box overlaps that.
          const std::array<int, 3> idx{i, j, k};
          bool overlaps = true;
          for (int a = 0; a < 3; ++a)
            overlaps = overlaps && box.max()[a] >= idx[a] * size && box.min()[a] <= idx[a] * size + size;
          if (overlaps) cells.insert({k, j, i});
        }
  };
  const bool distance = field.kind() == VolumeKind::DistanceField;
  std::vector<const FieldLeaf*> leaves;
  leaves.reserve(grid.tree().leafCount());
  grid.tree().getNodes(leaves);
  std::vector<char> near(leaves.size(), 0);
  const ScalarSides sides(iso, capsBox);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, leaves.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      const FieldGrid::ConstAccessor accessor = grid.getConstAccessor();
                      for (std::size_t i = r.begin(); i != r.end(); ++i) {
                        const FieldLeaf& leaf = *leaves[i];
                        if (!distance) {
                          near[i] = scalarLeafNearIso(leaf, accessor, sides);
                          continue;
                        }
                        for (auto it = leaf.cbeginValueAll(); it && !near[i]; ++it)
                          near[i] = std::abs(*it - iso) <= 1.f;
                      }
                    });
  partition.leavesScanned = static_cast<std::int64_t>(leaves.size());
  for (std::size_t i = 0; i < leaves.size(); ++i)
    if (near[i]) addBox(leaves[i]->getNodeBoundingBox());
  if (!distance) forEachActiveTile(grid.tree(), addBox);
  if (capsBox && backgroundInside(field, iso))
    for (int a = 0; a < 3; ++a) {
      const openvdb::Coord lo(capsBox->min[0], capsBox->min[1], capsBox->min[2]);
      const openvdb::Coord hi(capsBox->max[0], capsBox->max[1], capsBox->max[2]);
      openvdb::Coord faceHi = hi, faceLo = lo;
      faceHi[a] = lo[a];  // the face at the box's minimum on axis a
      faceLo[a] = hi[a];  // and at its maximum
      addBox(openvdb::CoordBBox(lo, faceHi));
      addBox(openvdb::CoordBBox(faceLo, hi));
    }
  for (const auto& zyx : cells) partition.cells.push_back({zyx[2], zyx[1], zyx[0]});
  return partition;
}

void readMetaCell(const Volume& field, const MetaCellIndex& index, int size, cell::MetaCellSamples& out, int apron,
                  const BlockWithoutLeaf& blockWithoutLeaf) {
  readBlock(field, {index[0] * size, index[1] * size, index[2] * size}, size, out, apron, blockWithoutLeaf);
}

void readBlock(const Volume& field, const std::array<int, 3>& origin, int size, cell::MetaCellSamples& out, int apron,
               const BlockWithoutLeaf& blockWithoutLeaf) {
  using Leaf = FieldGrid::TreeType::LeafNodeType;
  constexpr int kLeafDim = static_cast<int>(Leaf::DIM);
  const FieldGrid& grid = fieldGrid(field);
  // Every sample is written below (a leaf's values, or the value of the tile or
  // background that holds a leaf-sized block), so the block needs no fill.
  out.reshape(size, origin, apron);
  const int n = out.stride();
  const openvdb::Coord lo(origin[0] - apron, origin[1] - apron, origin[2] - apron);
  const openvdb::Coord hi = lo.offsetBy(n - 1);
  const std::size_t rowStride = static_cast<std::size_t>(n), sliceStride = rowStride * rowStride;
  auto accessor = grid.getConstAccessor();
  // One row of leaf-sized blocks along x at a time: its leaves (or their tile values) are
  // found once, then each of its 64 rows of samples is written whole, left to right. The
  // block is 130^3 samples and mostly background, so the writes dominate: leaf by leaf,
  // a row of 8 samples at a time, they jumped between 64 rows (this took 11 % of a regular
  // run on the 256^3 blobs). tools::copyToDense walks with z innermost, a strided write
  // per sample for this x-fastest block.
  const int firstBlockX = lo.x() & ~(kLeafDim - 1);
  const int blocksX = ((hi.x() - firstBlockX) >> Leaf::LOG2DIM) + 1;
  std::vector<const Leaf*> rowLeaves(static_cast<std::size_t>(blocksX));
  std::vector<float> rowTiles(static_cast<std::size_t>(blocksX));
  for (int bz = lo.z() & ~(kLeafDim - 1); bz <= hi.z(); bz += kLeafDim)
    for (int by = lo.y() & ~(kLeafDim - 1); by <= hi.y(); by += kLeafDim) {
      for (int b = 0; b < blocksX; ++b) {
        const int bx = firstBlockX + b * kLeafDim;
        const openvdb::Coord block(bx, by, bz);
        const Leaf* leaf = accessor.probeConstLeaf(block);
        rowLeaves[static_cast<std::size_t>(b)] = leaf;
        rowTiles[static_cast<std::size_t>(b)] = leaf               ? 0.0f
                                                : blockWithoutLeaf ? blockWithoutLeaf({bx, by, bz})
                                                                   : accessor.getValue(block);
      }
      const int z0 = std::max(bz, lo.z()), z1 = std::min(bz + kLeafDim - 1, hi.z());
      const int y0 = std::max(by, lo.y()), y1 = std::min(by + kLeafDim - 1, hi.y());
      for (int z = z0; z <= z1; ++z)
        for (int y = y0; y <= y1; ++y) {
          float* row = out.values.data() + static_cast<std::size_t>(z - lo.z()) * sliceStride +
                       static_cast<std::size_t>(y - lo.y()) * rowStride;
          // A leaf stores z fastest: offset (x << 6) + (y << 3) + z within it.
          const auto inLeaf = static_cast<std::size_t>(Leaf::coordToOffset(openvdb::Coord(0, y, z)));
          for (int b = 0; b < blocksX; ++b) {
            const int bx = firstBlockX + b * kLeafDim;
            const int x0 = std::max(bx, lo.x());
            float* to = row + (x0 - lo.x());
            const Leaf* leaf = rowLeaves[static_cast<std::size_t>(b)];
            if (leaf == nullptr) {  // with the blocks after it that hold the same value, in one fill
              const float tile = rowTiles[static_cast<std::size_t>(b)];
              while (b + 1 < blocksX && rowLeaves[static_cast<std::size_t>(b) + 1] == nullptr &&
                     rowTiles[static_cast<std::size_t>(b) + 1] == tile)
                ++b;
              const int x1 = std::min(firstBlockX + b * kLeafDim + kLeafDim - 1, hi.x());
              std::fill(to, to + (x1 - x0 + 1), tile);
              continue;
            }
            const int x1 = std::min(bx + kLeafDim - 1, hi.x());
            const float* column = leaf->buffer().data() + inLeaf;
            for (int x = x0; x <= x1; ++x)
              to[x - x0] = column[static_cast<std::size_t>(x & (kLeafDim - 1)) << (2 * Leaf::LOG2DIM)];
          }
        }
    }
}

bool hasSignChange(const cell::MetaCellSamples& samples, float iso) {
  // Row by row, each row's two answers or-ed over its samples without a branch (the
  // compiler vectorises it), and the rows' answers tested once per row: a block the
  // surface misses is read in full, and a dense field's block is 2 M samples.
  bool in = false, outside = false;
  const int s = samples.size;
  for (int k = 0; k <= s; ++k)
    for (int j = 0; j <= s; ++j) {
      const float* row = samples.values.data() + samples.indexOf(0, j, k);
      unsigned rowIn = 0, rowOutside = 0;
      for (int i = 0; i <= s; ++i) {
        const unsigned inside = cell::isInside(row[i], iso) ? 1u : 0u;
        rowIn |= inside;
        rowOutside |= inside ^ 1u;
      }
      in = in || rowIn != 0;
      outside = outside || rowOutside != 0;
      if (in && outside) return true;
    }
  return false;
}

}  // namespace isovdb::volume
