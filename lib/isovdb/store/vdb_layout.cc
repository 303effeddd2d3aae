// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/vdb_layout.h"

#include <openvdb/version.h>

#include <array>
#include <bit>
#include <fstream>

#include "isovdb/errors.h"
#include "isovdb/named_values.h"

namespace isovdb::store {

namespace {

constexpr std::int64_t kVdbMagic = 0x56444220;  // "VDB " (OpenVDB's OPENVDB_MAGIC)

/// Bytes of a metadata value of OpenVDB's fixed-size type `type`, -1 for other types.
/// OpenVDB reads such a value by its type's size, whatever size the item declares: a
/// "vec3i" of 12 bytes turned into a "vec4i" read 16, and the next item's length came
/// from the wrong bytes (a 1.7 GB name under ASan).
std::int64_t fixedMetadataSize(const std::string& type) {
  static constexpr NameTable<std::int64_t, 19> kSizes{{
      {1, "bool"},   {4, "int32"},  {4, "uint32"}, {8, "int64"},  {4, "float"},   {8, "double"}, {8, "vec2i"},
      {8, "vec2s"},  {16, "vec2d"}, {12, "vec3i"}, {12, "vec3s"}, {24, "vec3d"},  {16, "vec4i"}, {16, "vec4s"},
      {32, "vec4d"}, {36, "mat3s"}, {72, "mat3d"}, {64, "mat4s"}, {128, "mat4d"},
  }};
  return valueNamed(kSizes, type).value_or(-1);
}

/// Bounded little-endian reads of one file; every failure names the file and the record.
class LayoutReader {
 public:
  explicit LayoutReader(const std::filesystem::path& path) : path_(path), in_(path, std::ios::binary) {
    if (!in_) throw IoError("'" + path.string() + "': cannot open");
    std::error_code ec;
    size_ = static_cast<std::int64_t>(std::filesystem::file_size(path, ec));
    if (ec) throw IoError("'" + path.string() + "': cannot read its size (" + ec.message() + ")");
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError("'" + path_.string() + "': not a readable .vdb file: " + what);
  }

  std::int64_t size() const { return size_; }
  std::int64_t position() const { return position_; }
  std::int64_t remaining() const { return size_ - position_; }

  void seek(std::int64_t position, const char* what) {
    if (position < 0 || position > size_)
      fail(std::string(what) + " at byte " + std::to_string(position) + ", beyond the file's " + std::to_string(size_) +
           " bytes");
    in_.seekg(position);
    position_ = position;
  }

  void skip(std::int64_t bytes, const char* what) {
    if (bytes < 0 || bytes > remaining())
      fail(std::string(what) + " of " + std::to_string(bytes) + " bytes at byte " + std::to_string(position_) +
           " runs past the end of the file (" + std::to_string(size_) + " bytes)");
    seek(position_ + bytes, what);
  }

  /// A number in the file's byte order, which is the writer's native one (OpenVDB does not swap).
  template <class T>
  T number(const char* what) {
    if (remaining() < static_cast<std::int64_t>(sizeof(T)))
      fail(std::string("truncated in ") + what + " at byte " + std::to_string(position_));
    std::array<char, sizeof(T)> bytes{};
    in_.read(bytes.data(), sizeof(T));
    if (!in_) fail(std::string("read failed in ") + what + " at byte " + std::to_string(position_));
    position_ += static_cast<std::int64_t>(sizeof(T));
    return std::bit_cast<T>(bytes);
  }

  /// OpenVDB's string: a uint32 length, then the characters.
  std::string text(const char* what) {
    const auto length = static_cast<std::int64_t>(number<std::uint32_t>(what));
    if (length > remaining())
      fail(std::string(what) + ": a string of " + std::to_string(length) + " bytes at byte " +
           std::to_string(position_) + " runs past the end of the file (" + std::to_string(size_) + " bytes)");
    std::string s(static_cast<std::size_t>(length), '\0');
    in_.read(s.data(), length);
    position_ += length;
    return s;
  }

  /// The value of OpenVDB's DelayedLoadMetadata (`bytes` of them): a leaf count, then two
  /// per-leaf tables (1 and 8 bytes a leaf), each a uint32 compressed size and that many
  /// bytes, or the raw table when 0. OpenVDB sizes the tables from the count and allocates
  /// the compressed sizes before reading them (a count of 2^31 made it take 15 GB, a size
  /// of 4 GB asked for 4 GB), and reads what the structure says, not `bytes`.
  void delayedLoadTables(const char* what, std::int64_t bytes) {
    const std::int64_t end = position_ + bytes;
    const auto leaves = static_cast<std::int64_t>(number<std::uint32_t>(what));
    // Every leaf stores at least an 8-byte value mask in the file.
    if (leaves * 8 > size_)
      fail(std::string(what) + ": a delayed-load table of " + std::to_string(leaves) + " leaves, more than a file of " +
           std::to_string(size_) + " bytes can hold");
    for (const std::int64_t entryBytes : {1, 8}) {
      const auto compressed = static_cast<std::int64_t>(number<std::uint32_t>(what));
      const std::int64_t raw = leaves * entryBytes;
      if (compressed > raw + 16)  // blosc adds at most 16 bytes
        fail(std::string(what) + ": a delayed-load table of " + std::to_string(raw) + " bytes compressed into " +
             std::to_string(compressed));
      skip(compressed > 0 ? compressed : raw, what);
    }
    if (position_ != end)
      fail(std::string(what) + ": a delayed-load value of " + std::to_string(bytes) + " bytes holds " +
           std::to_string(position_ - (end - bytes)));
  }

  /// A MetaMap: a count, then (name, type name, uint32 size, value bytes) per item.
  void metadata(const char* what) {
    const std::uint32_t count = number<std::uint32_t>(what);
    // Each item takes at least 12 bytes (three lengths), so a count beyond that is corrupt.
    if (static_cast<std::int64_t>(count) * 12 > remaining())
      fail(std::string(what) + ": " + std::to_string(count) + " items cannot fit in the " +
           std::to_string(remaining()) + " bytes left");
    for (std::uint32_t i = 0; i < count; ++i) {
      text(what);
      const std::string type = text(what);
      const auto bytes = static_cast<std::int64_t>(number<std::uint32_t>(what));
      if (type == "__delayedload" && bytes > 0) {
        delayedLoadTables(what, bytes);
      } else {
        const std::int64_t expected = fixedMetadataSize(type);
        if (expected >= 0 && bytes != expected)
          fail(std::string(what) + ": an item of type " + type + " declares " + std::to_string(bytes) +
               " bytes, the type has " + std::to_string(expected));
        skip(bytes, what);
      }
    }
  }

 private:
  std::filesystem::path path_;
  std::ifstream in_;
  std::int64_t size_ = 0;
  std::int64_t position_ = 0;
};

/// Bytes OpenVDB's map of type `type` reads after its name (math/Maps.h: a Mat4d, or
/// Vec3d scale, voxel size and three inverses, with a translation), -1 for a map of
/// variable size (NonlinearFrustumMap) or an unknown name.
std::int64_t mapBytes(const std::string& type) {
  static constexpr NameTable<std::int64_t, 7> kSizes{{
      {128, "AffineMap"},
      {128, "UnitaryMap"},
      {120, "ScaleMap"},
      {120, "UniformScaleMap"},
      {24, "TranslationMap"},
      {144, "ScaleTranslateMap"},
      {144, "UniformScaleTranslateMap"},
  }};
  return valueNamed(kSizes, type).value_or(-1);
}

/// Bytes of a value of the trees this project reads (a root tile's value), -1 for others.
std::int64_t treeValueBytes(const std::string& type) {
  static constexpr NameTable<std::int64_t, 4> kSizes{{
      {4, "Tree_float_5_4_3"},
      {8, "Tree_double_5_4_3"},
      {1, "Tree_bool_5_4_3"},
      {1, "Tree_mask_5_4_3"},
  }};
  return valueNamed(kSizes, type).value_or(-1);
}

/// The root node's head of a grid's topology (tree/RootNode.h): a buffer count, the
/// background, the tile and child counts, then each tile (origin, value, active flag).
/// OpenVDB loops over the declared counts whatever the stream holds (a count of 2^32
/// spun for 10 s over a 39 KB file) and loads the flag, and a bool tree's value, into a
/// `bool` (a byte other than 0 or 1 is undefined behaviour).
void checkRootTopology(LayoutReader& in, const VdbGridRecord& grid, std::int64_t valueBytes, std::int64_t dataEnd) {
  in.number<std::int32_t>("grid topology");  // buffer count (OpenVDB warns when not 1)
  in.skip(valueBytes, "grid topology");      // background
  const auto tiles = static_cast<std::int64_t>(in.number<std::uint32_t>("grid topology"));
  const auto children = static_cast<std::int64_t>(in.number<std::uint32_t>("grid topology"));
  // A child of the root stores two 4096-byte masks at least; a tile its origin, value and flag.
  const std::int64_t tileBytes = 12 + valueBytes + 1;
  if (tiles * tileBytes + children * (12 + 8192) > dataEnd - in.position())
    in.fail("grid '" + grid.name + "': its root declares " + std::to_string(tiles) + " tiles and " +
            std::to_string(children) + " children, more than the " + std::to_string(dataEnd - in.position()) +
            " bytes of its topology can hold");
  const bool boolValues = grid.type == "Tree_bool_5_4_3";
  for (std::int64_t t = 0; t < tiles; ++t) {
    in.skip(12, "a root tile");
    for (std::int64_t b = 0; b < valueBytes; ++b) {
      const auto byte = in.number<std::uint8_t>("a root tile");
      if (boolValues && byte > 1)
        in.fail("grid '" + grid.name + "': root tile " + std::to_string(t) + " has the bool value " +
                std::to_string(byte));
    }
    const auto active = in.number<std::uint8_t>("a root tile");
    if (active > 1)
      in.fail("grid '" + grid.name + "': root tile " + std::to_string(t) + " has the active flag " +
              std::to_string(active) + " (0 or 1 expected)");
  }
}

/// The grid's own records from where its data starts: its compression word (file version
/// >= 222), its metadata and, in files of version 219 on (before 216 the transform
/// followed the topology), its transform, then the root of its topology, all before
/// `dataEnd` (its voxel buffers, or the file's end). OpenVDB allocates the map type
/// name's declared length before reading it: a damaged length made it build a 2 GB
/// string (10.8 s, then "KeyError: Map UniformScaleMap"). The topology is checked for
/// the trees and maps whose sizes are known, in grids that are not instances.
void checkGridHead(LayoutReader& in, const VdbGridRecord& grid, std::uint32_t version, std::int64_t dataEnd) {
  if (version >= openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION) in.number<std::uint32_t>("grid compression");
  in.metadata("grid metadata");
  if (version >= openvdb::OPENVDB_FILE_VERSION_NEW_TRANSFORM) {
    const std::int64_t map = mapBytes(in.text("grid transform"));
    const std::int64_t valueBytes = treeValueBytes(grid.type);
    if (map >= 0 && valueBytes >= 0 && grid.instanceParent.empty()) {
      in.skip(map, "grid transform");
      checkRootTopology(in, grid, valueBytes, dataEnd);
    }
  }
  if (in.position() > dataEnd)
    in.fail("grid '" + grid.name + "': its metadata, transform and topology run into its voxel data");
}

}  // namespace

VdbLayout checkVdbLayout(const std::filesystem::path& path) {
  LayoutReader in(path);
  VdbLayout layout;
  if (in.number<std::int64_t>("the header") != kVdbMagic) in.fail("no 'VDB ' magic number at its start");
  layout.fileVersion = in.number<std::uint32_t>("the header");
  if (layout.fileVersion < openvdb::OPENVDB_FILE_VERSION_ROOTNODE_MAP ||
      layout.fileVersion > openvdb::OPENVDB_FILE_VERSION)
    in.fail("file format version " + std::to_string(layout.fileVersion) + ", this OpenVDB reads " +
            std::to_string(openvdb::OPENVDB_FILE_VERSION_ROOTNODE_MAP) + " to " +
            std::to_string(openvdb::OPENVDB_FILE_VERSION));
  in.number<std::uint32_t>("the header");  // library major version
  in.number<std::uint32_t>("the header");  // library minor version
  const auto offsets = in.number<std::uint8_t>("the header");
  if (offsets > 1) in.fail("header flag 'has grid offsets' is " + std::to_string(offsets) + ", expected 0 or 1");
  layout.hasGridOffsets = offsets == 1;
  if (layout.fileVersion < openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION) in.number<std::uint8_t>("the header");
  in.skip(layout.fileVersion >= openvdb::OPENVDB_FILE_VERSION_BOOST_UUID ? 36 : 16, "the header's UUID");
  in.metadata("file metadata");
  const auto gridCount = in.number<std::int32_t>("the grid count");
  // A descriptor takes at least three lengths (and three offsets when the file has them).
  const std::int64_t smallestDescriptor = layout.hasGridOffsets ? 36 : 12;
  if (gridCount < 0 || static_cast<std::int64_t>(gridCount) * smallestDescriptor > in.remaining())
    in.fail("a count of " + std::to_string(gridCount) + " grids, which the " + std::to_string(in.remaining()) +
            " bytes left cannot hold");
  for (std::int32_t g = 0; g < gridCount; ++g) {
    VdbGridRecord grid;
    grid.name = in.text("a grid descriptor");
    grid.type = in.text("a grid descriptor");
    if (layout.fileVersion >= openvdb::OPENVDB_FILE_VERSION_GRID_INSTANCING)
      grid.instanceParent = in.text("a grid descriptor");
    if (!layout.hasGridOffsets) {
      // A stream-written file: the descriptor's offsets are there but meaningless, the grid's
      // data follows them, and the next descriptor follows that data, which only OpenVDB can
      // walk; the first grid's head is checked (fuzz_vdb: the flag cleared in a file with
      // offsets, and OpenVDB read a 4 GB delayed-load size from the grid's metadata).
      in.skip(24, "a grid descriptor");
      checkGridHead(in, grid, layout.fileVersion, in.size());
      layout.grids.push_back(grid);
      break;
    }
    const std::int64_t descriptorEnd = in.position() + 24;
    grid.gridPosition = in.number<std::int64_t>("a grid descriptor");
    grid.blockPosition = in.number<std::int64_t>("a grid descriptor");
    grid.endPosition = in.number<std::int64_t>("a grid descriptor");
    if (!(descriptorEnd <= grid.gridPosition && grid.gridPosition <= grid.blockPosition &&
          grid.blockPosition <= grid.endPosition && grid.endPosition <= in.size()))
      in.fail("grid '" + grid.name + "': its data offsets " + std::to_string(grid.gridPosition) + ", " +
              std::to_string(grid.blockPosition) + ", " + std::to_string(grid.endPosition) +
              " are out of order or beyond the file's " + std::to_string(in.size()) + " bytes (truncated?)");
    in.seek(grid.gridPosition, "grid data");
    checkGridHead(in, grid, layout.fileVersion, grid.blockPosition);
    layout.grids.push_back(grid);
    in.seek(grid.endPosition, "the next grid descriptor");
  }
  return layout;
}

}  // namespace isovdb::store
