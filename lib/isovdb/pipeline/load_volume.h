/// @file load_volume.h
/// @brief Opens any supported input (raw, NRRD, MetaImage, .vdb) as a sparse Volume.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "isovdb/io/raw_reader.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/progress.h"
#include "isovdb/volume/mask_rule.h"
#include "isovdb/volume/volume.h"

namespace isovdb::pipeline {

/// How a dense file's samples become a grid.
enum class DenseAs {
  Mask,    ///< binary mask by `rule` (the default: segmented volumes)
  Scalar,  ///< scalar field, contoured directly at the isovalue
};

struct InputOptions {
  std::optional<io::RawOptions> raw;  ///< dims and type of a headerless raw file
  DenseAs denseAs = DenseAs::Mask;
  volume::MaskRule rule;              ///< inside test for DenseAs::Mask
  std::string gridName;               ///< .vdb: grid to read (empty: first float/bool grid)
};

/// Reads `path` into a Volume, streaming dense files slab by slab. Records the
/// input's figures (format, dimensions, active voxels, leaves, tiles, memory)
/// in `stats` under "input".
/// @throw IoError (missing file), InputError (bad header or data; names the file).
volume::Volume loadVolume(const std::filesystem::path& path, const InputOptions& options,
                          Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

/// True when `path` names a .vdb file.
bool isVdbPath(const std::filesystem::path& path);

/// Adds a volume's grid figures (kind, active voxels, leaves, tiles, memory,
/// bounding box, value range) to `section`.
void recordGridStats(const volume::Volume& volume, Statistics::Json& section);

}  // namespace isovdb::pipeline
