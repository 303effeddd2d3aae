// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/ingest.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <openvdb/tools/Prune.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "isovdb/io/lazy_buffer.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/sampled_box.h"

namespace isovdb::volume {

namespace {

constexpr int kLeafDim = 8;                                   // OpenVDB leaf nodes are 8^3
constexpr int kPruneEvery = 128;                              // level-1 internal nodes span 128 voxels
constexpr std::size_t kClassifyGrain = std::size_t{1} << 16;  // samples per task of a slice's inside test
constexpr const char* kDeadBandKey = "isovdb_dead_band";

/// Maps stream coordinates (x fastest, z = slice) to grid coordinates (VolumeHeader::gridAxis).
struct AxisMap {
  std::array<int, 3> gridAxis;
  openvdb::Coord operator()(int x, int y, int z) const {
    openvdb::Coord c;
    c[gridAxis[0]] = x;
    c[gridAxis[1]] = y;
    c[gridAxis[2]] = z;
    return c;
  }
};

/// Where file voxel (x, y, z) lies in its 8^3 leaf's buffer (which stores grid voxel
/// (i, j, k) at i * 64 + j * 8 + k), for the file's axis order: blocks are filled by offset
/// into a local buffer, so no Coord is built per voxel and no leaf is allocated for a block
/// that turns out empty or constant.
struct LeafOffsets {
  std::array<int, 3> stride;  // per file axis
  explicit LeafOffsets(const AxisMap& toGrid) {
    constexpr std::array<int, 3> kGridStride{kLeafDim * kLeafDim, kLeafDim, 1};
    for (int a = 0; a < 3; ++a) stride[a] = kGridStride[static_cast<std::size_t>(toGrid.gridAxis[a])];
  }
  int operator()(int x, int y, int z) const {
    constexpr int kLow = kLeafDim - 1;
    return (x & kLow) * stride[0] + (y & kLow) * stride[1] + (z & kLow) * stride[2];
  }
};

Geometry geometryOf(const io::VolumeHeader& header) {
  Geometry geometry;
  for (int a = 0; a < 3; ++a) {
    geometry.spacing[header.gridAxis[a]] = header.spacing[a];
    geometry.origin[header.gridAxis[a]] = header.origin[a];
  }
  return geometry;
}

/// Records the file's dims, in grid axes, as the volume's sampled box.
Volume withSampledBox(Volume volume, const io::VolumeHeader& header) {
  IndexBox box;
  for (int a = 0; a < 3; ++a) {
    box.min[header.gridAxis[a]] = 0;
    box.max[header.gridAxis[a]] = static_cast<int>(header.dims[a] - 1);
  }
  setSampledBox(volume, box);
  return volume;
}

/// Reads up to 8 slices into `slab` (x fastest, then y, then z) and returns how many.
template <typename Classify>
int readSlab(io::SliceStream& stream, io::LazyBuffer<float>& slice, Classify&& store) {
  const io::VolumeHeader& header = stream.header();
  const std::int64_t remaining = header.dims[2] - stream.nextSlice();
  const int depth = static_cast<int>(std::min<std::int64_t>(kLeafDim, remaining));
  for (int z = 0; z < depth; ++z) {
    stream.readSlice(slice.data());
    store(z, slice);
  }
  return depth;
}

/// Moves past the slab of slices from `z0` when the stream says it holds no sample (outside
/// a SliceWindow): nothing to classify or insert. Returns whether it did.
bool skipBlankSlab(io::SliceStream& stream, std::int64_t z0, const ProgressStage& progress) {
  const std::int64_t depth = std::min<std::int64_t>(kLeafDim, stream.header().dims[2] - z0);
  if (!stream.blank(z0, depth)) return false;
  stream.skipSlices(depth);
  progress.update(static_cast<double>(z0 + depth), static_cast<double>(stream.header().dims[2]));
  return true;
}

/// One 8x8 column block of a slab: the leaf-sized block at (bx, by).
struct BlockRange {
  int x0, y0, x1, y1, depth;  // voxel range [x0,x1) x [y0,y1) x [0,depth)
  bool complete() const { return x1 - x0 == kLeafDim && y1 - y0 == kLeafDim && depth == kLeafDim; }
};

BlockRange blockRange(const io::VolumeHeader& header, int bx, int by, int depth) {
  const int x0 = bx * kLeafDim, y0 = by * kLeafDim;
  return BlockRange{x0, y0, static_cast<int>(std::min<std::int64_t>(x0 + kLeafDim, header.dims[0])),
                    static_cast<int>(std::min<std::int64_t>(y0 + kLeafDim, header.dims[1])), depth};
}

/// The words of an 8^3 leaf's mask: grid voxel (i, j, k) is bit i * 64 + j * 8 + k.
using LeafWords = std::array<std::uint64_t, 8>;

/// Adds to `words` the 0/1 bytes of a block whose file axes are the grid's (x fastest), 8
/// samples wide along x and y and `depth` slices deep, from `block` (sample (0, 0, 0)) with
/// these strides. Byte x of a row of 8 samples read as one little-endian word is sample x;
/// the rows of one y at z = 0..7, each shifted by z, add up to a word whose byte x holds the
/// column (x, y)'s 8 z bits, which is byte y of word x. Eight loads and eight byte moves per
/// 64 samples, where a shift and an or per sample was a sixth of reading a 1 GiB mask.
void gridOrderLeafWords(const std::uint8_t* block, std::int64_t rowStride, std::int64_t sliceStride, int depth,
                        LeafWords& words) {
  for (int y = 0; y < kLeafDim; ++y) {
    std::uint64_t columns = 0;
    for (int z = 0; z < depth; ++z) {
      std::uint64_t row = 0;
      std::memcpy(&row, block + z * sliceStride + y * rowStride, sizeof row);
      columns |= row << z;  // bytes are 0 or 1: nothing carries into the next byte
    }
    for (int x = 0; x < kLeafDim; ++x) words[static_cast<std::size_t>(x)] |= ((columns >> (8 * x)) & 0xFF) << (8 * y);
  }
}

/// What one 8^3 block of a slab becomes.
enum class BlockState : std::uint8_t { Empty, Tile, Leaf };

/// Inserts a slab's classified blocks serially, in block order, so the tree is
/// the same for any thread count. `tileValue(b)` is the value of a Tile block.
template <typename TreeT, typename TileValue>
void insertBlocks(TreeT& tree, const std::vector<BlockState>& state, std::vector<typename TreeT::LeafNodeType*>& leaves,
                  int blocksX, std::int64_t z0, const AxisMap& toGrid, TileValue&& tileValue) {
  for (std::size_t b = 0; b < state.size(); ++b) {
    const openvdb::Coord origin = toGrid(static_cast<int>(b % blocksX) * kLeafDim,
                                         static_cast<int>(b / blocksX) * kLeafDim, static_cast<int>(z0));
    if (state[b] == BlockState::Tile) tree.addTile(1, origin, tileValue(b), true);
    if (state[b] == BlockState::Leaf) {
      tree.addLeaf(leaves[b]);
      leaves[b] = nullptr;
    }
  }
}

void checkDims(const io::SliceStream& stream) {
  const auto& dims = stream.header().dims;
  constexpr std::int64_t kMaxDim = std::int64_t{1} << 30;  // openvdb::Coord is 32-bit
  for (int a = 0; a < 3; ++a)
    if (dims[a] <= 0 || dims[a] > kMaxDim)
      throw InputError("'" + stream.source() + "': dimension " + std::to_string(a) + " is " + std::to_string(dims[a]) +
                       ", expected 1.." + std::to_string(kMaxDim));
  std::array<int, 3> axes = stream.header().gridAxis;
  std::sort(axes.begin(), axes.end());
  if (axes != std::array<int, 3>{0, 1, 2})
    throw InputError("'" + stream.source() + "': grid axes are not a permutation of x, y, z");
}

}  // namespace

Volume ingestMask(io::SliceStream& stream, const MaskRule& rule, Interrupter* interrupter) {
  checkDims(stream);
  ProgressStage progress(interrupter, "ingest mask");
  const io::VolumeHeader& header = stream.header();
  const std::int64_t nx = header.dims[0], ny = header.dims[1], nz = header.dims[2];
  const int blocksX = static_cast<int>((nx + kLeafDim - 1) / kLeafDim);
  const int blocksY = static_cast<int>((ny + kLeafDim - 1) / kLeafDim);

  const AxisMap toGrid{header.gridAxis};
  const LeafOffsets offsetInLeaf(toGrid);
  const bool gridOrder = header.gridAxis == std::array<int, 3>{0, 1, 2} && std::endian::native == std::endian::little;
  auto grid = MaskGrid::create(false);
  MaskGrid::TreeType& tree = grid->tree();
  // Lazy buffers: sized from the declared dimensions, paid for as slices arrive.
  io::LazyBuffer<float> slice(static_cast<std::size_t>(nx * ny));
  io::LazyBuffer<std::uint8_t> inside(static_cast<std::size_t>(nx * ny * kLeafDim));
  std::vector<BlockState> state(static_cast<std::size_t>(blocksX) * blocksY);
  std::vector<MaskGrid::TreeType::LeafNodeType*> leaves(state.size(), nullptr);

  for (std::int64_t z0 = 0; z0 < nz; z0 += kLeafDim) {
    if (skipBlankSlab(stream, z0, progress)) continue;
    const int depth = readSlab(stream, slice, [&](int z, const io::LazyBuffer<float>& values) {
      std::uint8_t* out = inside.data() + static_cast<std::size_t>(z) * nx * ny;
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, values.size(), kClassifyGrain),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          rule.classify(std::span<const float>(values.data() + r.begin(), r.size()), out + r.begin());
                        });
    });
    // Classify the slab's blocks in parallel; leaves are allocated here too.
    tbb::parallel_for(0, blocksY, [&](int by) {
      for (int bx = 0; bx < blocksX; ++bx) {
        const BlockRange r = blockRange(header, bx, by, depth);
        using Leaf = MaskGrid::TreeType::LeafNodeType;
        LeafWords words{};
        if (gridOrder && r.x1 - r.x0 == kLeafDim && r.y1 - r.y0 == kLeafDim)
          gridOrderLeafWords(inside.data() + r.y0 * nx + r.x0, nx, nx * ny, r.depth, words);
        else
          for (int z = 0; z < r.depth; ++z)
            for (int y = r.y0; y < r.y1; ++y)
              for (int x = r.x0; x < r.x1; ++x) {
                const int offset = offsetInLeaf(x, y, z);
                words[static_cast<std::size_t>(offset >> 6)] |= std::uint64_t{inside[(z * ny + y) * nx + x]}
                                                                << (offset & 63);
              }
        Leaf::NodeMaskType on;
        for (openvdb::Index w = 0; w < Leaf::NodeMaskType::WORD_COUNT; ++w) on.getWord<std::uint64_t>(w) = words[w];
        const std::size_t b = static_cast<std::size_t>(by) * blocksX + bx;
        if (on.isOff()) {
          state[b] = BlockState::Empty;
        } else if (r.complete() && on.isOn()) {
          state[b] = BlockState::Tile;
        } else {
          state[b] = BlockState::Leaf;
          auto* leaf = new Leaf(toGrid(r.x0, r.y0, static_cast<int>(z0)), false, false);
          leaf->buffer() = Leaf::Buffer(on);  // inside voxels are on and true
          leaf->setValueMask(on);
          leaves[b] = leaf;
        }
      }
    });
    insertBlocks(tree, state, leaves, blocksX, z0, toGrid, [](std::size_t) { return true; });
    if ((z0 + kLeafDim) % kPruneEvery == 0) openvdb::tools::prune(tree);
    progress.update(static_cast<double>(z0 + depth), static_cast<double>(nz));
  }
  openvdb::tools::prune(tree);
  grid->setName("mask");
  return withSampledBox(Volume(VolumeKind::Mask, grid, geometryOf(header), stream.source()), header);
}

Volume ingestScalar(io::SliceStream& stream, const ScalarIngestOptions& options, Interrupter* interrupter) {
  checkDims(stream);
  ProgressStage progress(interrupter, "ingest scalar");
  const io::VolumeHeader& header = stream.header();
  const std::int64_t nx = header.dims[0], ny = header.dims[1], nz = header.dims[2];
  const int blocksX = static_cast<int>((nx + kLeafDim - 1) / kLeafDim);
  const int blocksY = static_cast<int>((ny + kLeafDim - 1) / kLeafDim);

  const AxisMap toGrid{header.gridAxis};
  const LeafOffsets offsetInLeaf(toGrid);
  auto grid = FieldGrid::create(options.background);
  FieldGrid::TreeType& tree = grid->tree();
  io::LazyBuffer<float> slice(static_cast<std::size_t>(nx * ny));
  io::LazyBuffer<float> slab(static_cast<std::size_t>(nx * ny * kLeafDim));
  std::vector<FieldGrid::TreeType::LeafNodeType*> leaves(static_cast<std::size_t>(blocksX) * blocksY);
  std::vector<BlockState> state(leaves.size());
  std::vector<float> tileValue(leaves.size());
  // The active values' range, per block of a slab and over the slabs: Volume::stats() then
  // need not read every value again (tools::minMax was 5 % of a dense field's run). Only
  // with an exact prune: a tolerance lets prune() replace values.
  std::vector<std::pair<float, float>> valueRanges(leaves.size());
  float rangeMin = std::numeric_limits<float>::max(), rangeMax = std::numeric_limits<float>::lowest();
  const float tol = options.tolerance;
  const float deadBand = options.deadBand;
  const auto isActive = [deadBand](float v) { return !std::isnan(v) && !(std::abs(v) < deadBand); };

  for (std::int64_t z0 = 0; z0 < nz; z0 += kLeafDim) {
    if (skipBlankSlab(stream, z0, progress)) continue;
    const int depth = readSlab(stream, slice, [&](int z, const io::LazyBuffer<float>& values) {
      std::copy(values.begin(), values.end(), slab.begin() + static_cast<std::ptrdiff_t>(z * nx * ny));
    });
    tbb::parallel_for(0, blocksY, [&](int by) {
      for (int bx = 0; bx < blocksX; ++bx) {
        const BlockRange r = blockRange(header, bx, by, depth);
        const std::size_t b = static_cast<std::size_t>(by) * blocksX + bx;
        using Leaf = FieldGrid::TreeType::LeafNodeType;
        std::array<float, Leaf::SIZE> values;  // inactive voxels hold the background
        values.fill(options.background);
        Leaf::NodeMaskType on;
        int active = 0;
        float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
        for (int z = 0; z < r.depth; ++z)
          for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) {
              const float v = slab[(z * ny + y) * nx + x];
              if (!isActive(v)) continue;
              const auto offset = static_cast<openvdb::Index>(offsetInLeaf(x, y, z));
              values[offset] = v;
              on.setOn(offset);
              ++active;
              lo = std::min(lo, v);
              hi = std::max(hi, v);
            }
        const bool all = active == r.depth * (r.y1 - r.y0) * (r.x1 - r.x0);
        const bool constant = all && hi - lo <= tol;
        if (active == 0 ||
            (constant && std::abs(lo - options.background) <= tol && std::abs(hi - options.background) <= tol)) {
          state[b] = BlockState::Empty;
          continue;
        }
        valueRanges[b] = {lo, hi};
        if (constant && r.complete()) {
          state[b] = BlockState::Tile;
          tileValue[b] = lo;
        } else {
          state[b] = BlockState::Leaf;
          auto* leaf = new Leaf(toGrid(r.x0, r.y0, static_cast<int>(z0)), options.background, false);
          std::copy(values.begin(), values.end(), leaf->buffer().data());
          leaf->setValueMask(on);
          leaves[b] = leaf;
        }
      }
    });
    for (std::size_t b = 0; b < state.size(); ++b)
      if (state[b] != BlockState::Empty) {
        rangeMin = std::min(rangeMin, valueRanges[b].first);
        rangeMax = std::max(rangeMax, valueRanges[b].second);
      }
    insertBlocks(tree, state, leaves, blocksX, z0, toGrid, [&](std::size_t b) { return tileValue[b]; });
    if ((z0 + kLeafDim) % kPruneEvery == 0) openvdb::tools::prune(tree, tol);
    progress.update(static_cast<double>(z0 + depth), static_cast<double>(nz));
  }
  openvdb::tools::prune(tree, tol);
  grid->setName("field");
  if (deadBand > 0) grid->insertMeta(kDeadBandKey, openvdb::FloatMetadata(deadBand));
  Volume volume = withSampledBox(Volume(VolumeKind::Scalar, grid, geometryOf(header), stream.source()), header);
  if (tol == 0.0f && rangeMin <= rangeMax) volume.setValueRange(rangeMin, rangeMax);
  return volume;
}

Volume ingestSignedDistances(io::SliceStream& stream, int halfWidth, Interrupter* interrupter) {
  const Geometry geometry = geometryOf(stream.header());
  if (!geometry.isUniform())
    throw InputError("'" + stream.source() + "': signed distances need the same voxel size on the three axes, got " +
                     std::to_string(geometry.spacing[0]) + ", " + std::to_string(geometry.spacing[1]) + ", " +
                     std::to_string(geometry.spacing[2]));
  if (halfWidth < 1) throw InputError("half-width: expected at least 1 voxel, got " + std::to_string(halfWidth));
  // A background no finite sample has keeps every sample active; the band is cut by value below.
  const Volume samples = ingestScalar(stream, {.background = std::numeric_limits<float>::max()}, interrupter);
  const FieldGrid::Ptr grid = fieldGridPtr(samples);
  const float toVoxels = static_cast<float>(1.0 / geometry.spacing[0]);
  const auto width = static_cast<float>(halfWidth);
  for (auto it = grid->beginValueOn(); it; ++it) {  // serial: tiles' active bits live in shared nodes
    const float d = *it * toVoxels;
    if (std::abs(d) < width) {
      it.setValue(d);
    } else {
      it.setValue(d < 0 ? -width : width);
      it.setValueOff();
    }
  }
  grid->tree().root().setBackground(width, /*updateChildNodes=*/true);  // beyond the samples: outside
  openvdb::tools::pruneLevelSet(grid->tree());
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  return Volume(VolumeKind::DistanceField, grid, geometry, samples.name());
}

}  // namespace isovdb::volume

namespace isovdb::volume {

float deadBandOf(const Volume& volume) {
  if (!volume.grid()) return 0.f;
  const auto meta = volume.grid()->getMetadata<openvdb::FloatMetadata>(kDeadBandKey);
  return meta ? meta->value() : 0.f;
}

}  // namespace isovdb::volume
