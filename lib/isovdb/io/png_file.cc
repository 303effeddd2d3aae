// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/png_file.h"

#include <stb_image_write.h>

#include <string>

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"

namespace isovdb::io {

void writePng(const std::filesystem::path& path, int width, int height, int channels,
              const std::vector<std::uint8_t>& pixels) {
  if (width <= 0 || height <= 0 || (channels != 1 && channels != 3) ||
      pixels.size() !=
          static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * static_cast<std::size_t>(channels))
    throw InputError("'" + path.string() + "': " + std::to_string(pixels.size()) + " bytes for a " +
                     std::to_string(width) + "x" + std::to_string(height) + " picture of " + std::to_string(channels) +
                     " channels");
  // stb calls back from C: collect the bytes, write them (and maybe throw) afterwards.
  std::string png;
  const int ok = stbi_write_png_to_func(
      [](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<char*>(data), size); },
      &png, width, height, channels, pixels.data(), width * channels);
  if (!ok) throw IoError("'" + path.string() + "': PNG encoding failed");
  AtomicFile file(path);
  file.write(png);
  file.commit();
}

}  // namespace isovdb::io
