// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file slice_stack.h
/// @brief A stack of parallel planar slices (binary, one canvas size) with their
///        heights, read from a folder of images or from a sparse-z binary volume.
///
/// Heights are in world units, increasing. Pixel (x, y) of every slice is at
/// world (x * pixelSize, y * pixelSize); slices smaller than the canvas are
/// padded with outside pixels on the right and at the bottom (paper 002 §3.3.1).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "isovdb/morph/plane.h"
#include "isovdb/volume/volume.h"

namespace isovdb::morph {

struct Slice {
  Mask2 mask;          ///< canvas-sized
  double height = 0;   ///< world units
  std::string source;  ///< file (or "volume z=K") for messages
};

struct SliceStack {
  int width = 0, height = 0;  ///< canvas, pixels
  double pixelSize = 1.0;     ///< world units per pixel (x and y)
  Vec2 origin;                ///< world position of pixel (0, 0)
  /// World units per voxel along z in the reconstructed volume (originals snap
  /// to the nearest plane; see reconstruct.h).
  double zStep = 1.0;
  std::vector<Slice> slices;  ///< strictly increasing heights
};

struct SliceDirectoryOptions {
  /// Text file of heights, one number per slice (whitespace or newline separated).
  std::filesystem::path heightsFile;
  /// Uniform spacing between consecutive slices when no heights file is given.
  double spacing = 0;
  double pixelSize = 1.0;  ///< world units per pixel
  /// Most pixels one image may have: its header is checked before it is decoded (a 439 KB
  /// PNG declaring 20000 x 20000 pixels took 5.5 GB). 2^28: a 16384 x 16384 slice.
  std::int64_t maxPixels = std::int64_t{1} << 28;
};

/// @brief Reads every .png/.bmp in `dir` (natural order of the names: 2 before 10)
///        and assigns heights.
/// @throw IoError (missing folder); InputError naming the file or flag: no slice image,
///        an unreadable image, neither or both of heightsFile/spacing, a heights count
///        that differs from the image count, heights not strictly increasing.
SliceStack loadSliceDirectory(const std::filesystem::path& dir, const SliceDirectoryOptions& options);

/// Reads a heights file. @throw IoError / InputError (names the file and the line).
std::vector<double> readHeights(const std::filesystem::path& path);

/// @throw InputError naming `what` unless the heights strictly increase.
void checkIncreasing(const std::vector<double>& heights, const std::string& what);

struct VolumeSliceOptions {
  /// Labelled z-slices are z = offset + k * step (sampled-box indices); 0: every
  /// z-slice with inside voxels (an empty labelled slice cannot be told apart).
  int step = 0;
  int offset = 0;
};

/// @brief The labelled z-slices of a binary (mask) volume, e.g. a manual segmentation
///        that labels every k-th slice. Heights are z * spacing[2]; pixel size spacing[0].
/// @throw InputError when the volume is not a mask, has unequal x/y spacing or no
///        labelled slice.
SliceStack sliceStackFromVolume(const volume::Volume& mask, const VolumeSliceOptions& options);

}  // namespace isovdb::morph
