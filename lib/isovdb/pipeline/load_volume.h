// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file load_volume.h
/// @brief Opens any supported input (raw, NRRD, MetaImage, SEG-Y, .vdb) as a sparse Volume.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "isovdb/io/raw_reader.h"
#include "isovdb/io/segy_reader.h"
#include "isovdb/io/slice_window.h"
#include "isovdb/pipeline/statistics.h"
#include "isovdb/progress.h"
#include "isovdb/volume/distance_field.h"
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
  /// Read as SEG-Y, with these header byte positions; .sgy/.segy files are SEG-Y
  /// without it (with the default positions).
  std::optional<io::SegyOptions> segy;
  DenseAs denseAs = DenseAs::Mask;
  volume::MaskRule rule;  ///< inside test for DenseAs::Mask
  /// DenseAs::Scalar: clip value. Samples with |value| < clip stay inactive and the
  /// grid's background is the clip value (a quiet amplitude cube costs little).
  /// 0 keeps every sample.
  float clip = 0.f;
  /// Also record the samples' range, percentiles and the fraction |value| >= clip
  /// under "input.samples" (gathered during the same read; 12 MiB of histograms).
  bool sampleStatistics = false;
  std::string gridName;  ///< .vdb: grid to read (empty: first float/bool grid)
  /// Read only the samples whose grid z lies in this window (one slab of a distributed
  /// run, io/slice_window.h): the others are holes; dims, geometry and sampled box stay
  /// the file's. Dense files and SEG-Y only.
  std::optional<io::SliceWindow> window;
};

/// Reads `path` into a Volume, streaming dense files slab by slab and SEG-Y files
/// line by line (its survey geometry goes into the grid's metadata). Records the
/// input's figures (format, dimensions, SEG-Y geometry, active voxels, leaves,
/// tiles, memory) in `stats` under "input".
/// @throw IoError (missing file), InputError (bad header or data; names the file).
volume::Volume loadVolume(const std::filesystem::path& path, const InputOptions& options,
                          Interrupter* interrupter = nullptr, Statistics* stats = nullptr);

/// True when `path` names a .vdb file.
bool isVdbPath(const std::filesystem::path& path);

/// Adds a volume's grid figures (kind, active voxels, leaves, tiles, memory,
/// bounding box, value range) to `section`.
void recordGridStats(const volume::Volume& volume, Statistics::Json& section);

/// The "distance_field" section of a mask's band: the settings it was made with.
Statistics::Json distanceFieldSection(const volume::DistanceFieldOptions& options);

/// Adds the figures of a band never held as one grid (streamed to a .vdb, or made
/// one layer of meta-cells at a time) to `section`, under recordGridStats' keys.
/// `Figures` has leafCount, activeVoxels, bboxMin, bboxMax, minValue and maxValue.
template <typename Figures>
void recordBandFigures(const Figures& figures, const volume::Geometry& geometry, Statistics::Json& section) {
  section["kind"] = std::string(volume::volumeKindName(volume::VolumeKind::DistanceField));
  section["active_voxels"] = figures.activeVoxels;
  section["leaf_nodes"] = figures.leafCount;
  section["active_tiles"] = 0;
  section["bbox_min"] = figures.bboxMin;
  section["bbox_max"] = figures.bboxMax;
  section["spacing"] = geometry.spacing;
  section["origin"] = geometry.origin;
  section["min_value"] = figures.minValue;
  section["max_value"] = figures.maxValue;
}

}  // namespace isovdb::pipeline
