// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/slice_image.h"

#include <stb_image.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "isovdb/errors.h"
#include "isovdb/io/png_check.h"
#include "isovdb/io/png_file.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/path_util.h"
#include "isovdb/morph/contour_fill.h"

namespace isovdb::morph {

bool isSliceImagePath(const std::filesystem::path& path) {
  const std::string ext = io::lowerExtension(path);
  return ext == ".png" || ext == ".bmp";
}

Mask2 readSliceImage(const std::filesystem::path& path, std::int64_t maxPixels) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("'" + path.string() + "': cannot open slice image (no such file or not readable)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  io::checkPngData(bytes, path.string());  // stb_image grows its buffers from what the data says
  int width = 0, height = 0, channels = 0;
  // The header's size first: decoding allocates it before reading a single pixel.
  // A top-down BMP declares a negative height, which stb_image's info reports as is
  // (and its decoder as the absolute value): the fuzzer's 8 x -16,777,208 passed as
  // fewer pixels than the limit.
  if (stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), static_cast<int>(bytes.size()), &width,
                            &height, &channels)) {
    const std::int64_t w = std::abs(static_cast<std::int64_t>(width)), h = std::abs(static_cast<std::int64_t>(height));
    if (w * h > maxPixels)
      throw InputError("'" + path.string() + "': the image declares " + std::to_string(w) + " x " + std::to_string(h) +
                       " pixels, more than --max-pixels " + std::to_string(maxPixels));
  }
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                          static_cast<int>(bytes.size()), &width, &height, &channels, 1);
  if (!pixels)
    throw InputError("'" + path.string() + "': not a readable PNG or BMP image (" + stbi_failure_reason() + ")");
  if (width <= 0 || height <= 0) {  // stb_image decodes a BMP of width 0 (fuzz_slice_image)
    stbi_image_free(pixels);
    throw InputError("'" + path.string() + "': the image has no pixels (" + std::to_string(width) + " x " +
                     std::to_string(height) + ")");
  }
  Mask2 dark = Mask2::empty(width, height);
  for (std::size_t i = 0; i < dark.inside.size(); ++i) dark.inside[i] = pixels[i] < 128 ? 1 : 0;
  stbi_image_free(pixels);

  // The class holding most of the border is the background.
  std::int64_t borderDark = 0, border = 0;
  for (int x = 0; x < width; ++x) {
    borderDark += dark.at(x, 0) + dark.at(x, height - 1);
    border += 2;
  }
  for (int y = 0; y < height; ++y) {
    borderDark += dark.at(0, y) + dark.at(width - 1, y);
    border += 2;
  }
  if (2 * borderDark > border)
    for (std::uint8_t& v : dark.inside) v = 1 - v;
  return fillContours(dark);
}

void writeSliceImage(const std::filesystem::path& path, const Mask2& mask) {
  std::vector<std::uint8_t> grey(mask.inside.size());
  for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = mask.inside[i] ? 255 : 0;
  io::writePng(path, mask.width, mask.height, 1, grey);
}

}  // namespace isovdb::morph
