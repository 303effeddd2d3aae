// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/leafwise_level_set_writer.h"

#include <openvdb/io/Compression.h>
#include <openvdb/io/Archive.h>
#include <openvdb/io/DelayedLoadMetadata.h>
#include <openvdb/io/GridDescriptor.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <deque>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "isovdb/errors.h"
#include "isovdb/io/path_util.h"
#include "isovdb/store/vdb_grid_setup.h"

namespace isovdb::store {

namespace {

using io::quoted;

using Tree = volume::FieldGrid::TreeType;
using UpperNode = Tree::RootNodeType::ChildNodeType;  // 4096^3 voxels, 32^3 slots
using LowerNode = UpperNode::ChildNodeType;           // 128^3 voxels, 16^3 slots
using LeafRecord = LeafwiseLevelSetWriter::LeafRecord;

/// Why a stream's write failed: the system's reason when the write set errno (cleared
/// before it; a full disk: "No space left on device"), else the likely one.
std::string streamError() { return errno != 0 ? std::strerror(errno) : "the disk may be full"; }

/// A child of an internal node as the flood fill sees it: its slot and the values
/// at its first and last voxel.
struct ChildSigns {
  openvdb::Index slot;
  float first, last;
};

/// OpenVDB's SignedFloodFillOp rule for an internal node (tools/SignedFloodFill.h),
/// restated for a node that is not in memory: walking the slots in x-major order,
/// each tile takes the sign of the nearest child before it on its z-row, else its
/// y-row, else its x-row, starting from the first child's first value.
/// `children` is sorted by slot and not empty.
template <typename NodeT>
std::vector<float> floodTiles(const std::vector<ChildSigns>& children, float inside, float outside) {
  constexpr openvdb::Index kDim = 1u << NodeT::LOG2DIM;
  std::vector<int> childAt(NodeT::NUM_VALUES, -1);
  for (std::size_t i = 0; i < children.size(); ++i) childAt[children[i].slot] = static_cast<int>(i);
  std::vector<float> tiles(NodeT::NUM_VALUES, outside);
  bool xInside = children.front().first < 0, yInside = xInside, zInside = xInside;
  for (openvdb::Index x = 0; x != kDim; ++x) {
    const openvdb::Index x00 = x << (2 * NodeT::LOG2DIM);
    if (childAt[x00] >= 0) xInside = children[childAt[x00]].last < 0;
    yInside = xInside;
    for (openvdb::Index y = 0; y != kDim; ++y) {
      const openvdb::Index xy0 = x00 + (y << NodeT::LOG2DIM);
      if (childAt[xy0] >= 0) yInside = children[childAt[xy0]].last < 0;
      zInside = yInside;
      for (openvdb::Index z = 0; z != kDim; ++z) {
        const openvdb::Index xyz = xy0 + z;
        if (childAt[xyz] >= 0)
          zInside = children[childAt[xyz]].last < 0;
        else
          tiles[xyz] = zInside ? inside : outside;
      }
    }
  }
  return tiles;
}

/// One internal node of the tree being written: a run of children (leaf records
/// for a lower node, lower nodes for an upper one), its flood-filled tiles, and
/// whether it keeps any child after level-set pruning.
struct InternalRecord {
  openvdb::Coord origin;
  std::size_t begin = 0, end = 0;  ///< children's range
  float first = 0.f, last = 0.f;   ///< after the flood fill, before pruning
  bool active = false;             ///< holds a child that is not pruned
};

/// The topology of the tree, built from the sorted leaf records with the same
/// flood fill and pruning as tools::signedFloodFill and tools::pruneLevelSet.
struct Skeleton {
  const std::deque<LeafRecord>& leaves;
  std::vector<InternalRecord> lowers, uppers;
  std::map<openvdb::Coord, float> rootTiles;  ///< inactive tiles at the root (inside ones only)
  float inside, outside;

  /// Values of an internal node's slots after the flood fill and pruning:
  /// children kept are 0 there (as OpenVDB writes them) and set in `kept`;
  /// children pruned become tiles of the sign of their first value.
  template <typename NodeT, typename Children, typename IsKept>
  std::vector<float> nodeValues(const Children& all, const InternalRecord& node, IsKept isKept,
                                openvdb::util::NodeMask<NodeT::LOG2DIM>& kept) const {
    std::vector<ChildSigns> signs;
    for (std::size_t i = node.begin; i != node.end; ++i)
      signs.push_back({NodeT::coordToOffset(all[i].origin), all[i].first, all[i].last});
    std::vector<float> values = floodTiles<NodeT>(signs, inside, outside);
    kept.setOff();
    for (std::size_t i = node.begin; i != node.end; ++i) {
      const openvdb::Index slot = NodeT::coordToOffset(all[i].origin);
      if (isKept(all[i])) {
        kept.setOn(slot);
        values[slot] = 0.f;
      } else {
        values[slot] = all[i].first < 0 ? inside : outside;
      }
    }
    return values;
  }

  std::vector<float> lowerValues(const InternalRecord& lower, openvdb::util::NodeMask<4>& kept) const {
    return nodeValues<LowerNode>(
        leaves, lower, [](const LeafRecord& leaf) { return leaf.bytes > 0; }, kept);
  }
  std::vector<float> upperValues(const InternalRecord& upper, openvdb::util::NodeMask<5>& kept) const {
    return nodeValues<UpperNode>(
        lowers, upper, [](const InternalRecord& lower) { return lower.active; }, kept);
  }

  Skeleton(const std::deque<LeafRecord>& sortedLeaves, float background)
      : leaves(sortedLeaves), inside(-background), outside(background) {
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      const openvdb::Coord origin = leaves[i].origin & ~(LowerNode::DIM - 1);
      if (lowers.empty() || lowers.back().origin != origin) lowers.push_back({origin, i, i});
      lowers.back().end = i + 1;
      lowers.back().active = lowers.back().active || leaves[i].bytes > 0;
    }
    openvdb::util::NodeMask<4> lowerChildren;
    for (InternalRecord& lower : lowers) {
      const std::vector<float> values = lowerValues(lower, lowerChildren);
      // First and last values before pruning, as the fill one level up reads them;
      // a pruned leaf's tile has the sign of its first value, so pruning keeps them.
      const LeafRecord& front = leaves[lower.begin];
      const LeafRecord& back = leaves[lower.end - 1];
      const bool frontAtZero = LowerNode::coordToOffset(front.origin) == 0;
      const bool backAtEnd = LowerNode::coordToOffset(back.origin) == LowerNode::NUM_VALUES - 1;
      lower.first = frontAtZero ? front.first : values[0];
      lower.last = backAtEnd ? back.last : values[LowerNode::NUM_VALUES - 1];
    }
    for (std::size_t i = 0; i < lowers.size(); ++i) {
      const openvdb::Coord origin = lowers[i].origin & ~(UpperNode::DIM - 1);
      if (uppers.empty() || uppers.back().origin != origin) uppers.push_back({origin, i, i});
      uppers.back().end = i + 1;
      uppers.back().active = uppers.back().active || lowers[i].active;
    }
    openvdb::util::NodeMask<5> upperChildren;
    for (InternalRecord& upper : uppers) {
      const std::vector<float> values = upperValues(upper, upperChildren);
      const InternalRecord& front = lowers[upper.begin];
      const InternalRecord& back = lowers[upper.end - 1];
      upper.first = UpperNode::coordToOffset(front.origin) == 0 ? front.first : values[0];
      upper.last = UpperNode::coordToOffset(back.origin) == UpperNode::NUM_VALUES - 1
                       ? back.last
                       : values[UpperNode::NUM_VALUES - 1];
    }
    // The root's rule: inside tiles only between two inside children on one z-line.
    for (std::size_t i = 1; i < uppers.size(); ++i) {
      const InternalRecord& a = uppers[i - 1];
      const InternalRecord& b = uppers[i];
      const openvdb::Coord d = b.origin - a.origin;
      if (d[0] != 0 || d[1] != 0 || d[2] == static_cast<int>(UpperNode::DIM)) continue;
      if (!(a.last < 0) || !(b.first < 0)) continue;
      for (openvdb::Coord c = a.origin.offsetBy(0, 0, UpperNode::DIM); c[2] != b.origin[2]; c[2] += UpperNode::DIM)
        rootTiles[c] = inside;
    }
    // Pruning at the root, then eraseBackgroundTiles: an upper node without
    // children leaves a tile only when it is inside.
    for (const InternalRecord& upper : uppers)
      if (!upper.active && upper.first < 0) rootTiles[upper.origin] = inside;
  }
};

/// A level-set grid whose tree is not in memory: its name, class, transform and
/// metadata are a grid's, and these two overrides write the topology from the
/// skeleton and the leaf blocks from the spill file, in the byte layout of
/// Tree::writeTopology / Tree::writeBuffers.
class SpilledLevelSetGrid : public openvdb::FloatGrid {
 public:
  SpilledLevelSetGrid(const Skeleton& skeleton, std::ifstream& spill, std::uint32_t compression, float background,
                      const ProgressStage& progress)
      : openvdb::FloatGrid(background),
        skeleton_(skeleton),
        spill_(spill),
        compression_(compression),
        background_(background),
        progress_(progress) {}

  void writeTopology(std::ostream& os) const override {
    if (saveFloatAsHalf()) throw std::logic_error("leafwise level-set writer: half floats are not supported");
    tree().TreeBase::writeTopology(os, false);  // the buffer count
    os.write(reinterpret_cast<const char*>(&background_), sizeof(float));
    openvdb::io::setGridBackgroundValuePtr(os, &background_);
    std::vector<const InternalRecord*> children;
    for (const InternalRecord& upper : skeleton_.uppers)
      if (upper.active) children.push_back(&upper);
    const auto tileCount = static_cast<openvdb::Index>(skeleton_.rootTiles.size());
    const auto childCount = static_cast<openvdb::Index>(children.size());
    os.write(reinterpret_cast<const char*>(&tileCount), sizeof(openvdb::Index));
    os.write(reinterpret_cast<const char*>(&childCount), sizeof(openvdb::Index));
    if (tileCount == 0 && childCount == 0) return;
    const bool inactive = false;
    for (const auto& [origin, value] : skeleton_.rootTiles) {
      os.write(reinterpret_cast<const char*>(origin.asPointer()), 3 * sizeof(openvdb::Int32));
      os.write(reinterpret_cast<const char*>(&value), sizeof(float));
      os.write(reinterpret_cast<const char*>(&inactive), sizeof(bool));
    }
    for (const InternalRecord* upper : children) {
      os.write(reinterpret_cast<const char*>(upper->origin.asPointer()), 3 * sizeof(openvdb::Int32));
      writeUpperTopology(os, *upper);
    }
  }

  void writeBuffers(std::ostream& os) const override {
    if (openvdb::io::getDataCompression(os) != compression_)
      throw std::logic_error("leafwise level-set writer: the file's compression differs from the spilled leaves'");
    std::vector<char> block;
    std::size_t written = 0;
    for (const InternalRecord& upper : skeleton_.uppers) {
      if (!upper.active) continue;
      for (std::size_t l = upper.begin; l != upper.end; ++l) {
        const InternalRecord& lower = skeleton_.lowers[l];
        for (std::size_t i = lower.begin; i != lower.end; ++i) {
          const LeafRecord& leaf = skeleton_.leaves[i];
          if (leaf.bytes == 0) continue;
          block.resize(leaf.bytes);
          spill_.seekg(static_cast<std::streamoff>(leaf.offset));
          spill_.read(block.data(), leaf.bytes);
          if (!spill_) throw std::runtime_error("the spilled leaf blocks could not be read back");
          os.write(block.data(), leaf.bytes);
          if (++written % 4096 == 0)
            progress_.update(static_cast<double>(i), static_cast<double>(skeleton_.leaves.size()));
        }
      }
    }
  }

 private:
  /// InternalNode::writeTopology's own part: the child mask, the value mask (a
  /// level set has no active tiles) and every slot's value.
  template <openvdb::Index Log2>
  static void writeInternalNode(std::ostream& os, std::vector<float>& values,
                                const openvdb::util::NodeMask<Log2>& children) {
    children.save(os);
    const openvdb::util::NodeMask<Log2> noActiveTiles;
    noActiveTiles.save(os);
    openvdb::io::writeCompressedValues(os, values.data(), static_cast<openvdb::Index>(values.size()), noActiveTiles,
                                       children, false);
  }

  void writeUpperTopology(std::ostream& os, const InternalRecord& upper) const {
    openvdb::util::NodeMask<5> children;
    std::vector<float> values = skeleton_.upperValues(upper, children);
    writeInternalNode(os, values, children);
    for (std::size_t l = upper.begin; l != upper.end; ++l)
      if (skeleton_.lowers[l].active) writeLowerTopology(os, skeleton_.lowers[l]);
  }

  void writeLowerTopology(std::ostream& os, const InternalRecord& lower) const {
    openvdb::util::NodeMask<4> children;
    std::vector<float> values = skeleton_.lowerValues(lower, children);
    writeInternalNode(os, values, children);
    for (std::size_t i = lower.begin; i != lower.end; ++i)
      if (skeleton_.leaves[i].bytes > 0) skeleton_.leaves[i].valueMask.save(os);
  }

  const Skeleton& skeleton_;
  std::ifstream& spill_;
  std::uint32_t compression_;
  float background_;
  const ProgressStage& progress_;
};

/// io::Archive::write for one grid whose tree is not in memory. Archive would
/// compute the delayed-load table and the statistics from the (empty) tree, so
/// this writes the same sequence with the table made from the leaf records.
class SingleLevelSetArchive : public openvdb::io::Archive {
 public:
  using openvdb::io::Archive::write;  // the overloads for grids in memory stay visible
  void write(std::ostream& os, const SpilledLevelSetGrid& grid, const openvdb::MetaMap& gridMetadata) const {
    auto fileMetadata = std::make_shared<openvdb::io::StreamMetadata>();
    openvdb::io::setStreamMetadataPtr(os, fileMetadata, /*transfer=*/false);
    openvdb::io::setDataCompression(os, compression());
    openvdb::io::setWriteGridStatsMetadata(os, false);
    writeHeader(os, /*seekable=*/true);
    openvdb::MetaMap().writeMeta(os);
    const std::int32_t gridCount = 1;
    os.write(reinterpret_cast<const char*>(&gridCount), sizeof(gridCount));

    auto gridStreamMetadata = std::make_shared<openvdb::io::StreamMetadata>(*fileMetadata);
    gridStreamMetadata->setHalfFloat(false);
    gridStreamMetadata->gridMetadata() = gridMetadata;
    openvdb::io::setStreamMetadataPtr(os, gridStreamMetadata, /*transfer=*/false);
    openvdb::io::GridDescriptor descriptor(grid.getName(), grid.type(), /*saveFloatAsHalf=*/false);
    descriptor.writeHeader(os);
    const std::streamoff offsetsAt = os.tellp();
    descriptor.writeStreamPos(os);  // placeholders, rewritten below
    descriptor.setGridPos(os.tellp());
    setGridCompression(os, grid);
    gridMetadata.writeMeta(os);
    grid.writeTransform(os);
    grid.writeTopology(os);
    descriptor.setBlockPos(os.tellp());
    grid.writeBuffers(os);
    descriptor.setEndPos(os.tellp());
    os.seekp(offsetsAt, std::ios_base::beg);
    descriptor.writeStreamPos(os);
    descriptor.seekToEnd(os);
    openvdb::io::clearStreamMetadataPtr(os);
  }
};

/// Tree order: root table (origins of upper nodes, lexicographic), then slot in
/// the upper node, then slot in the lower node.
auto treeOrder(const LeafRecord& leaf) {
  return std::make_tuple(leaf.origin & ~(UpperNode::DIM - 1), UpperNode::coordToOffset(leaf.origin),
                         LowerNode::coordToOffset(leaf.origin));
}

}  // namespace

LeafwiseLevelSetWriter::LeafwiseLevelSetWriter(std::filesystem::path path, float halfWidth,
                                               const volume::Geometry& geometry, Options options)
    : path_(std::move(path)),
      target_(path_),
      scale_(levelSetWorldScale(geometry)),
      background_(halfWidth * scale_),
      geometry_(geometry),
      options_(std::move(options)),
      // What io::File writes a level set with: its default flags without zlib.
      compression_(openvdb::io::Archive::DEFAULT_COMPRESSION_FLAGS & ~openvdb::io::COMPRESS_ZIP) {
  initializeOpenVdb();
  target_.closeStream();
  spillPath_ = target_.temporaryPath();
  spillPath_ += ".leaves";
  spill_.open(spillPath_, std::ios::binary | std::ios::trunc);
  if (!spill_) throw IoError("cannot write " + quoted(path_) + ": cannot create the spill file " + quoted(spillPath_));
}

LeafwiseLevelSetWriter::~LeafwiseLevelSetWriter() {
  spill_.close();
  std::error_code ec;
  std::filesystem::remove(spillPath_, ec);
}

void LeafwiseLevelSetWriter::add(std::vector<std::unique_ptr<volume::FieldLeaf>>&& leaves) {
  // Everything per leaf (statistics, units, serialisation, the archive's sizes)
  // happens before the lock, so threads adding chunks at once only queue for
  // the spill file's append.
  std::ostringstream block;
  openvdb::io::setDataCompression(block, compression_);
  openvdb::io::setGridBackgroundValuePtr(block, &background_);
  std::vector<LeafRecord> records;
  records.reserve(leaves.size());
  std::string bytes;
  LevelSetFileSummary batch;
  for (std::unique_ptr<volume::FieldLeaf>& leaf : leaves) {
    LeafRecord record;
    record.origin = leaf->origin();
    record.valueMask = leaf->getValueMask();
    if (!record.valueMask.isOff()) {
      openvdb::CoordBBox box;
      leaf->evalActiveBoundingBox(box);
      if (batch.activeVoxels == 0) {
        batch.bboxMin = {box.min().x(), box.min().y(), box.min().z()};
        batch.bboxMax = {box.max().x(), box.max().y(), box.max().z()};
        batch.minValue = batch.maxValue = *leaf->cbeginValueOn();
      }
      for (int a = 0; a < 3; ++a) {
        batch.bboxMin[a] = std::min(batch.bboxMin[a], box.min()[a]);
        batch.bboxMax[a] = std::max(batch.bboxMax[a], box.max()[a]);
      }
      for (auto v = leaf->cbeginValueOn(); v; ++v) {
        batch.minValue = std::min(batch.minValue, *v);
        batch.maxValue = std::max(batch.maxValue, *v);
      }
      batch.activeVoxels += static_cast<std::int64_t>(record.valueMask.countOn());
      ++batch.leafCount;
    }
    // World units, as writeVdb's scaleLevelSet + changeLevelSetBackground give them.
    if (scale_ != 1.f)
      for (auto v = leaf->beginValueAll(); v; ++v)
        v.setValue(v.isValueOn() ? *v * scale_ : (*v < 0 ? -background_ : background_));
    record.first = leaf->getFirstValue();
    record.last = leaf->getLastValue();
    if (!record.valueMask.isOff()) {
      block.str({});
      leaf->writeBuffers(block, /*toHalf=*/false);
      const std::string leafBytes = block.str();
      const openvdb::io::MaskCompress<float, openvdb::util::NodeMask<3>> maskCompress(
          record.valueMask, openvdb::util::NodeMask<3>(), leaf->buffer().data(), background_);
      record.maskCompression = maskCompress.metadata;
      record.compressedBytes = static_cast<std::int64_t>(openvdb::io::writeCompressedValuesSize(
                                   leaf->buffer().data(), volume::FieldLeaf::SIZE, record.valueMask,
                                   maskCompress.metadata, false, compression_)) +
                               static_cast<std::int64_t>(sizeof(std::int64_t));  // as Archive counts it
      record.offset = bytes.size();  // within this batch until the append below
      record.bytes = static_cast<std::uint32_t>(leafBytes.size());
      bytes += leafBytes;
    }
    records.push_back(record);
    leaf.reset();
  }

  const std::lock_guard<std::mutex> lock(mutex_);
  errno = 0;
  spill_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!spill_)
    throw IoError("cannot write " + quoted(path_) + ": writing the spill file " + quoted(spillPath_) +
                  " failed: " + streamError());
  for (LeafRecord& record : records) {
    if (record.bytes) record.offset += spillOffset_;
    records_.push_back(record);
  }
  spillOffset_ += bytes.size();
  if (batch.activeVoxels > 0) {
    if (summary_.activeVoxels == 0) {
      summary_.bboxMin = batch.bboxMin;
      summary_.bboxMax = batch.bboxMax;
      summary_.minValue = batch.minValue;
      summary_.maxValue = batch.maxValue;
    }
    for (int a = 0; a < 3; ++a) {
      summary_.bboxMin[a] = std::min(summary_.bboxMin[a], batch.bboxMin[a]);
      summary_.bboxMax[a] = std::max(summary_.bboxMax[a], batch.bboxMax[a]);
    }
    summary_.minValue = std::min(summary_.minValue, batch.minValue);
    summary_.maxValue = std::max(summary_.maxValue, batch.maxValue);
    summary_.activeVoxels += batch.activeVoxels;
    summary_.leafCount += batch.leafCount;
  }
}

LevelSetFileSummary LeafwiseLevelSetWriter::commit(Interrupter* interrupter) {
  ProgressStage progress(interrupter, "writing .vdb");
  spill_.close();
  if (!spill_)
    throw IoError("cannot write " + quoted(path_) + ": closing the spill file " + quoted(spillPath_) + " failed");
  std::sort(records_.begin(), records_.end(),
            [](const LeafRecord& a, const LeafRecord& b) { return treeOrder(a) < treeOrder(b); });
  for (std::size_t i = 1; i < records_.size(); ++i)
    if (records_[i].origin == records_[i - 1].origin) {
      std::ostringstream origin;
      origin << records_[i].origin;
      throw std::logic_error("leafwise level-set writer: leaf " + origin.str() + " was added twice");
    }
  const Skeleton skeleton(records_, background_);

  std::ifstream spill(spillPath_, std::ios::binary);
  if (!spill) throw IoError("cannot write " + quoted(path_) + ": cannot reopen the spill file " + quoted(spillPath_));
  auto grid = std::make_shared<SpilledLevelSetGrid>(skeleton, spill, compression_, background_, progress);
  describeGrid(*grid, geometry_, options_.gridName, /*levelSet=*/true, options_.source);
  // What io::Archive adds to a grid's metadata when it writes it: the table a
  // delayed-loading reader uses to skip leaf blocks, and the statistics.
  openvdb::MetaMap metadata(static_cast<const openvdb::MetaMap&>(*grid));
  {
    openvdb::io::DelayedLoadMetadata table;
    const std::size_t blocks = static_cast<std::size_t>(summary_.leafCount);
    if (blocks > 0) {
      table.resizeMask(blocks);
      if (compression_ & (openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ZIP)) table.resizeCompressedSize(blocks);
      std::size_t index = 0;
      for (const InternalRecord& upper : skeleton.uppers)
        for (std::size_t l = upper.begin; l != upper.end; ++l)
          for (std::size_t i = skeleton.lowers[l].begin; i != skeleton.lowers[l].end; ++i) {
            const LeafRecord& leaf = records_[i];
            if (leaf.bytes == 0) continue;
            table.setMask(index, leaf.maskCompression);
            if (compression_ & (openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ZIP))
              table.setCompressedSize(index, leaf.compressedBytes);
            ++index;
          }
      metadata.insertMeta(openvdb::GridBase::META_FILE_DELAYED_LOAD, table);
    }
  }
  if (summary_.activeVoxels > 0) {
    metadata.insertMeta(
        openvdb::GridBase::META_FILE_BBOX_MIN,
        openvdb::Vec3IMetadata(openvdb::Vec3i(summary_.bboxMin[0], summary_.bboxMin[1], summary_.bboxMin[2])));
    metadata.insertMeta(
        openvdb::GridBase::META_FILE_BBOX_MAX,
        openvdb::Vec3IMetadata(openvdb::Vec3i(summary_.bboxMax[0], summary_.bboxMax[1], summary_.bboxMax[2])));
  }
  metadata.insertMeta(openvdb::GridBase::META_FILE_VOXEL_COUNT, openvdb::Int64Metadata(summary_.activeVoxels));
  metadata.insertMeta(openvdb::GridBase::META_FILE_COMPRESSION,
                      openvdb::StringMetadata(openvdb::io::compressionToString(compression_)));
  try {
    std::ofstream out(target_.temporaryPath(), std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open the temporary file");
    SingleLevelSetArchive archive;
    archive.setCompression(compression_);
    errno = 0;
    archive.write(out, *grid, metadata);
    out.close();
    if (!out) throw std::runtime_error("writing failed: " + streamError());
  } catch (const openvdb::Exception& e) {
    throw IoError("cannot write " + quoted(path_) + ": " + std::string(e.what()));
  } catch (const std::runtime_error& e) {
    throw IoError("cannot write " + quoted(path_) + ": " + std::string(e.what()));
  }
  spill.close();
  std::error_code ignored;
  std::filesystem::remove(spillPath_, ignored);
  summary_.spillBytes = static_cast<std::int64_t>(spillOffset_);
  summary_.fileBytes = static_cast<std::int64_t>(std::filesystem::file_size(target_.temporaryPath()));
  target_.commit();
  progress.update(1, 1);
  return summary_;
}

}  // namespace isovdb::store
