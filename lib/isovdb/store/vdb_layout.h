// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file vdb_layout.h
/// @brief Checks a `.vdb` file's header and grid table before OpenVDB reads it.
///
/// OpenVDB's reader trusts the lengths and offsets it reads: a flipped byte in a
/// string length makes it allocate gigabytes, a truncated file can make it spin.
/// This walk reads the same records (header, file metadata, grid descriptors,
/// each grid's compression word, metadata, transform and root tiles) and checks every length and offset
/// against the file's size, so that what OpenVDB then allocates for them is
/// bounded by the bytes actually present. It reads no voxel data; corruption
/// inside a grid's topology or buffers is left to OpenVDB's own checks, whose
/// exceptions vdb_file turns into errors naming the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace isovdb::store {

/// One grid descriptor of a .vdb file.
struct VdbGridRecord {
  std::string name;                ///< unique name, as stored
  std::string type;                ///< e.g. "Tree_float_5_4_3"
  std::string instanceParent;      ///< the grid whose tree this one shares; empty if none
  std::int64_t gridPosition = 0;   ///< metadata, transform and topology start here
  std::int64_t blockPosition = 0;  ///< voxel buffers start here
  std::int64_t endPosition = 0;    ///< the next descriptor starts here
};

struct VdbLayout {
  std::uint32_t fileVersion = 0;
  bool hasGridOffsets = false;  ///< false: a stream-written file, whose grids are checked up to the first
  std::vector<VdbGridRecord> grids;
};

/// Walks the header and the grid table of `path`.
/// @throw InputError naming the file, the record and what is wrong (bad magic,
///        unsupported version, a length or offset beyond the end of the file).
VdbLayout checkVdbLayout(const std::filesystem::path& path);

}  // namespace isovdb::store
