// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/lazy_buffer.h"
#include "isovdb/volume/digital_topology.h"

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "isovdb/volume/grids.h"

namespace isovdb::volume {

namespace {

/// Contribution to chi of the cells owned by a lattice vertex p, indexed by the
/// 2x2x2 configuration around p. Bit b = dx + 2*dy + 4*dz of the configuration
/// is the voxel with minimum corner p + (dx-1, dy-1, dz-1).
///
/// p owns: itself; the edges p->p+ex, p->p+ey, p->p+ez; the squares spanned by
/// two of those edges; the cube with minimum corner p. A cell is in the object
/// iff one of the voxels containing it is, e.g. the edge p->p+ex iff a voxel
/// with dx = 1 is (bits 1, 3, 5, 7 = 0xAA).
constexpr std::array<std::int8_t, 256> makeEulerTable() {
  std::array<std::int8_t, 256> table{};
  for (int config = 0; config < 256; ++config) {
    const auto any = [config](int bits) { return (config & bits) != 0 ? 1 : 0; };
    const int vertex = any(0xFF);
    const int edges = any(0xAA) + any(0xCC) + any(0xF0);    // +x, +y, +z
    const int squares = any(0x88) + any(0xA0) + any(0xC0);  // xy, xz, yz
    const int cube = any(0x80);
    table[config] = static_cast<std::int8_t>(vertex - edges + squares - cube);
  }
  return table;
}

constexpr std::array<std::int8_t, 256> kEulerTable = makeEulerTable();

/// The (6, 18) counterpart. The object is the cubical complex whose vertices are
/// the voxel centres, with an edge for each pair of face-adjacent inside voxels, a
/// square for each 2x2 block and a cube for each 2x2x2 block of inside voxels —
/// which is (6, 26) — plus, for 18-adjacent background, a hexagonal disc filling
/// each window whose only background voxels are two opposite (body-diagonal)
/// corners: with 18-adjacency those two do not touch, so the six inside voxels
/// around them enclose no tunnel. Each vertex, edge and square is owned by the
/// window whose voxel 7 (dx = dy = dz = 1) is its maximum voxel; cubes and discs
/// by their own window.
constexpr std::array<std::int8_t, 256> makeEulerTable6() {
  std::array<std::int8_t, 256> table{};
  for (int config = 0; config < 256; ++config) {
    const auto all = [config](int bits) { return (config & bits) == bits ? 1 : 0; };
    const int vertex = all(0x80);
    const int edges = all(0xC0) + all(0xA0) + all(0x88);    // x, y, z neighbours of voxel 7
    const int squares = all(0xF0) + all(0xCC) + all(0xAA);  // xy, xz, yz blocks holding voxel 7
    const int cube = all(0xFF);
    int disc = 0;
    for (int corner = 0; corner < 4; ++corner)
      disc += config == (0xFF & ~((1 << corner) | (1 << (7 - corner)))) ? 1 : 0;
    table[config] = static_cast<std::int8_t>(vertex - edges + squares + disc - cube);
  }
  return table;
}

constexpr std::array<std::int8_t, 256> kEulerTable6 = makeEulerTable6();

static_assert(kEulerTable6[0x80] == 1, "a lone voxel counts once, as its own maximum voxel");
static_assert(kEulerTable6[0xFF] == 0, "full neighbourhood contributes nothing");

const std::array<std::int8_t, 256>& eulerTable(Adjacency adjacency) {
  return adjacency == Adjacency::Foreground6 ? kEulerTable6 : kEulerTable;
}

static_assert(kEulerTable[0x00] == 0, "empty neighbourhood contributes nothing");
static_assert(kEulerTable[0xFF] == 0, "full neighbourhood contributes nothing");
static_assert(kEulerTable[0x01] == 1, "the top corner of a lone voxel is its only count");

/// Sums the table over the lattice vertices of the layers between consecutive
/// z-slices. Slices are stored with one background voxel of padding on each
/// side in x and y, so the vertices on the volume boundary need no special case.
class SlicePairAccumulator {
 public:
  SlicePairAccumulator(std::int64_t nx, std::int64_t ny, const std::array<std::int8_t, 256>& table)
      : table_(table),
        nx_(nx),
        ny_(ny),
        stride_(nx + 2),
        below_(static_cast<std::size_t>((nx + 2) * (ny + 2)), 0),
        above_(below_.size(), 0) {}

  /// Row y (0 <= y < ny) of the slice being filled: nx bytes, 0 or 1.
  std::uint8_t* row(std::int64_t y) { return above_.data() + (y + 1) * stride_ + 1; }

  /// Adds the vertex layer between the previous slice and the one just filled,
  /// then makes the filled slice the previous one. The first call sees an
  /// all-background previous slice.
  void addSlice() {
    const std::uint8_t* below = below_.data();
    const std::uint8_t* above = above_.data();
    const std::int64_t stride = stride_;
    const std::int64_t nx = nx_;
    const std::array<std::int8_t, 256>& table = table_;
    chi_ += tbb::parallel_reduce(
        tbb::blocked_range<std::int64_t>(0, ny_ + 1, 64), std::int64_t{0},
        [=, &table](const tbb::blocked_range<std::int64_t>& rows, std::int64_t sum) {
          for (std::int64_t py = rows.begin(); py != rows.end(); ++py) {
            // Vertex (px, py) sees padded voxels px, px+1 of rows py, py+1.
            const std::uint8_t* b0 = below + py * stride;
            const std::uint8_t* b1 = b0 + stride;
            const std::uint8_t* a0 = above + py * stride;
            const std::uint8_t* a1 = a0 + stride;
            const auto column = [&](std::int64_t x) {
              return static_cast<unsigned>(b0[x] | (b1[x] << 2) | (a0[x] << 4) | (a1[x] << 6));
            };
            unsigned left = column(0);
            for (std::int64_t px = 0; px <= nx; ++px) {
              const unsigned right = column(px + 1);
              sum += table[left | (right << 1)];
              left = right;
            }
          }
          return sum;
        },
        [](std::int64_t a, std::int64_t b) { return a + b; });
    std::swap(below_, above_);
  }

  /// Adds the last vertex layer (above the last slice, against the background).
  std::int64_t finish() {
    for (std::int64_t y = 0; y < ny_; ++y) std::fill_n(row(y), nx_, std::uint8_t{0});
    addSlice();
    return chi_;
  }

 private:
  const std::array<std::int8_t, 256>& table_;
  std::int64_t nx_, ny_, stride_;
  std::vector<std::uint8_t> below_, above_;
  std::int64_t chi_ = 0;
};

/// Writes the active states of voxels [x0, x1] of row (y, z) into `out`,
/// one leaf-node block at a time (a tile covers whole blocks).
template <typename AccessorT>
void fillMaskRow(AccessorT& accessor, int x0, int x1, int y, int z, std::uint8_t* out) {
  constexpr int kLeafDim = static_cast<int>(MaskGrid::TreeType::LeafNodeType::DIM);
  for (int x = x0; x <= x1;) {
    const int blockEnd = std::min(x1, (x & ~(kLeafDim - 1)) + kLeafDim - 1);
    const openvdb::Coord xyz(x, y, z);
    if (const auto* leaf = accessor.probeConstLeaf(xyz)) {
      for (int xi = x; xi <= blockEnd; ++xi) out[xi - x0] = leaf->isValueOn(openvdb::Coord(xi, y, z)) ? 1 : 0;
    } else {
      std::fill(out + (x - x0), out + (blockEnd - x0) + 1, static_cast<std::uint8_t>(accessor.isValueOn(xyz) ? 1 : 0));
    }
    x = blockEnd + 1;
  }
}

}  // namespace

std::int64_t eulerCharacteristic(io::SliceStream& stream, const MaskRule& rule, Interrupter* interrupter,
                                 Adjacency adjacency) {
  const io::VolumeHeader& header = stream.header();
  const std::int64_t nx = header.dims[0], ny = header.dims[1], nz = header.dims[2];
  if (nx <= 0 || ny <= 0 || nz <= 0) return 0;

  ProgressStage stage(interrupter, "euler characteristic");
  SlicePairAccumulator accumulator(nx, ny, eulerTable(adjacency));
  io::LazyBuffer<float> values(static_cast<std::size_t>(nx * ny));  // touched as slices arrive
  for (std::int64_t z = stream.nextSlice(); z < nz; ++z) {
    stage.update(static_cast<double>(z), static_cast<double>(nz));
    stream.readSlice(values.data());
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, ny, 16), [&](const tbb::blocked_range<std::int64_t>& rows) {
      for (std::int64_t y = rows.begin(); y != rows.end(); ++y) {
        rule.classify(std::span<const float>(values.data() + y * nx, static_cast<std::size_t>(nx)), accumulator.row(y));
      }
    });
    accumulator.addSlice();
  }
  return accumulator.finish();
}

std::int64_t eulerCharacteristic(const Volume& mask, Interrupter* interrupter, Adjacency adjacency) {
  const MaskGrid& grid = maskGrid(mask);
  openvdb::CoordBBox bbox;
  if (!grid.tree().evalActiveVoxelBoundingBox(bbox)) return 0;

  ProgressStage stage(interrupter, "euler characteristic");
  const openvdb::Coord lo = bbox.min(), hi = bbox.max();
  const std::int64_t nx = std::int64_t{hi.x()} - lo.x() + 1;
  const std::int64_t ny = std::int64_t{hi.y()} - lo.y() + 1;
  const std::int64_t nz = std::int64_t{hi.z()} - lo.z() + 1;
  SlicePairAccumulator accumulator(nx, ny, eulerTable(adjacency));
  for (int z = lo.z(); z <= hi.z(); ++z) {
    stage.update(static_cast<double>(z - lo.z()), static_cast<double>(nz));
    tbb::parallel_for(tbb::blocked_range<std::int64_t>(0, ny, 16), [&](const tbb::blocked_range<std::int64_t>& rows) {
      MaskGrid::ConstAccessor accessor = grid.getConstAccessor();
      for (std::int64_t y = rows.begin(); y != rows.end(); ++y)
        fillMaskRow(accessor, lo.x(), hi.x(), lo.y() + static_cast<int>(y), z, accumulator.row(y));
    });
    accumulator.addSlice();
  }
  return accumulator.finish();
}

}  // namespace isovdb::volume
