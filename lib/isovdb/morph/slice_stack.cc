// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/slice_stack.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "isovdb/errors.h"
#include "isovdb/morph/slice_image.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/sampled_box.h"

namespace isovdb::morph {

namespace {

/// Natural order: digit runs compare as numbers ("s2" < "s10").
bool naturalLess(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) && std::isdigit(static_cast<unsigned char>(b[j]))) {
      std::size_t ie = i, je = j;
      while (ie < a.size() && std::isdigit(static_cast<unsigned char>(a[ie]))) ++ie;
      while (je < b.size() && std::isdigit(static_cast<unsigned char>(b[je]))) ++je;
      const std::string na = a.substr(i, ie - i), nb = b.substr(j, je - j);
      const auto strip = [](const std::string& s) { return s.substr(std::min(s.find_first_not_of('0'), s.size())); };
      const std::string sa = strip(na), sb = strip(nb);
      if (sa.size() != sb.size()) return sa.size() < sb.size();
      if (sa != sb) return sa < sb;
      i = ie;
      j = je;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

/// Pads every slice to the largest width and height (outside pixels right and below).
void padToCanvas(SliceStack& stack) {
  for (const Slice& s : stack.slices) {
    stack.width = std::max(stack.width, s.mask.width);
    stack.height = std::max(stack.height, s.mask.height);
  }
  for (Slice& s : stack.slices) {
    if (s.mask.width == stack.width && s.mask.height == stack.height) continue;
    Mask2 padded = Mask2::empty(stack.width, stack.height);
    for (int y = 0; y < s.mask.height; ++y)
      for (int x = 0; x < s.mask.width; ++x) padded.set(x, y, s.mask.at(x, y));
    s.mask = std::move(padded);
  }
}

}  // namespace

std::vector<double> readHeights(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw IoError("'" + path.string() + "': cannot open heights file (no such file or not readable)");
  std::vector<double> heights;
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::string word;
    while (words >> word) {
      std::size_t used = 0;
      double value = 0;
      try {
        value = std::stod(word, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != word.size() || !std::isfinite(value))
        throw InputError("'" + path.string() + "': line " + std::to_string(lineNo) + ": '" + word +
                         "' is not a number (expected one height per slice)");
      heights.push_back(value);
    }
  }
  return heights;
}

void checkIncreasing(const std::vector<double>& heights, const std::string& what) {
  for (std::size_t i = 1; i < heights.size(); ++i)
    if (!(heights[i] > heights[i - 1]))
      throw InputError(what + ": heights must increase strictly, but height " + std::to_string(i + 1) + " (" +
                       std::to_string(heights[i]) + ") follows " + std::to_string(heights[i - 1]));
}

SliceStack loadSliceDirectory(const std::filesystem::path& dir, const SliceDirectoryOptions& options) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw IoError("'" + dir.string() + "': no such slice folder");
  if (options.heightsFile.empty() == (options.spacing <= 0))
    throw InputError("'" + dir.string() + "': give either --heights FILE or --spacing DZ (> 0)");
  if (!(options.pixelSize > 0)) throw InputError("--pixel-size must be > 0");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    // entry.is_regular_file() follows links: a link loop is skipped, not an internal error.
    if (!isSliceImagePath(entry.path())) continue;
    if (entry.is_regular_file(ec)) {
      files.push_back(entry.path());
    } else if (ec) {
      throw InputError("'" + entry.path().string() + "': cannot read this slice image (" + ec.message() + ")");
    }
  }
  if (files.empty()) throw InputError("'" + dir.string() + "': no slice images (.png or .bmp) in the folder");
  std::sort(files.begin(), files.end(),
            [](const auto& a, const auto& b) { return naturalLess(a.filename().string(), b.filename().string()); });

  std::vector<double> heights;
  if (!options.heightsFile.empty()) {
    heights = readHeights(options.heightsFile);
    if (heights.size() != files.size())
      throw InputError("'" + options.heightsFile.string() + "': " + std::to_string(heights.size()) + " heights for " +
                       std::to_string(files.size()) + " slice images in '" + dir.string() + "'");
    checkIncreasing(heights, "'" + options.heightsFile.string() + "'");
  } else {
    for (std::size_t i = 0; i < files.size(); ++i) heights.push_back(static_cast<double>(i) * options.spacing);
  }

  SliceStack stack;
  stack.pixelSize = options.pixelSize;
  stack.zStep = options.pixelSize;
  for (std::size_t i = 0; i < files.size(); ++i)
    stack.slices.push_back({readSliceImage(files[i], options.maxPixels), heights[i], files[i].string()});
  padToCanvas(stack);
  return stack;
}

SliceStack sliceStackFromVolume(const volume::Volume& volume, const VolumeSliceOptions& options) {
  if (volume.kind() != volume::VolumeKind::Mask)
    throw InputError("'" + volume.name() + "': slices come from a binary volume (use --threshold or --labels)");
  const volume::Geometry& g = volume.geometry();
  if (g.spacing[0] != g.spacing[1]) throw InputError("'" + volume.name() + "': slices need equal x and y spacing");
  if (options.step < 0 || options.offset < 0) throw InputError("--slice-step and --slice-offset must be >= 0");
  const volume::MaskGrid& grid = volume::maskGrid(volume);
  volume::IndexBox box;
  if (const auto sampled = volume::sampledBox(volume)) {
    box = *sampled;
  } else {
    const openvdb::CoordBBox b = grid.evalActiveVoxelBoundingBox();
    box.min = {b.min().x(), b.min().y(), b.min().z()};
    box.max = {b.max().x(), b.max().y(), b.max().z()};
  }
  SliceStack stack;
  stack.width = box.max[0] - box.min[0] + 1;
  stack.height = box.max[1] - box.min[1] + 1;
  stack.pixelSize = g.spacing[0];
  stack.zStep = g.spacing[2];
  stack.origin = {g.origin[0] + box.min[0] * g.spacing[0], g.origin[1] + box.min[1] * g.spacing[1]};
  if (stack.width <= 0 || stack.height <= 0) throw InputError("'" + volume.name() + "': empty volume");
  auto acc = grid.getConstAccessor();
  for (int z = box.min[2]; z <= box.max[2]; ++z) {
    const int k = z - box.min[2];
    if (options.step > 0 && (k < options.offset || (k - options.offset) % options.step != 0)) continue;
    Mask2 mask = Mask2::empty(stack.width, stack.height);
    for (int y = 0; y < stack.height; ++y)
      for (int x = 0; x < stack.width; ++x)
        mask.set(x, y, acc.isValueOn(openvdb::Coord(box.min[0] + x, box.min[1] + y, z)));
    if (options.step == 0 && mask.area() == 0) continue;
    stack.slices.push_back({std::move(mask), g.origin[2] + z * g.spacing[2], "z=" + std::to_string(z)});
  }
  if (stack.slices.empty()) throw InputError("'" + volume.name() + "': no labelled z-slice");
  return stack;
}

}  // namespace isovdb::morph
