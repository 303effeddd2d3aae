// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/png_check.h"

#include <zlib.h>

#include <array>
#include <cstdint>
#include <optional>

#include "isovdb/errors.h"

namespace isovdb::io {

namespace {

constexpr std::string_view kPngSignature{"\x89PNG\r\n\x1a\n", 8};

std::uint32_t bigEndian32(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

/// Bytes of filtered image data (a filter byte per row) an image of this header holds:
/// one pass, or Adam7's seven.
std::uint64_t filteredBytes(std::uint64_t width, std::uint64_t height, std::uint64_t bitsPerPixel, bool interlaced) {
  const auto passBytes = [&](std::uint64_t w, std::uint64_t h) {
    return w == 0 || h == 0 ? 0 : h * ((w * bitsPerPixel + 7) / 8 + 1);
  };
  if (!interlaced) return passBytes(width, height);
  constexpr std::array<std::array<std::uint64_t, 4>, 7> kAdam7{
      {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4}, {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}}};
  std::uint64_t total = 0;
  for (const auto& [x0, y0, dx, dy] : kAdam7)
    total += passBytes(width > x0 ? (width - x0 + dx - 1) / dx : 0, height > y0 ? (height - y0 + dy - 1) / dy : 0);
  return total;
}

/// Inflates the IDAT chunks' data one after another, counting what comes out.
class InflateCounter {
 public:
  InflateCounter() { ok_ = inflateInit(&stream_) == Z_OK; }
  ~InflateCounter() { inflateEnd(&stream_); }
  InflateCounter(const InflateCounter&) = delete;
  InflateCounter& operator=(const InflateCounter&) = delete;

  /// Feeds `data`; stops counting (and stays false) at the stream's end or an error.
  void feed(std::string_view data) {
    stream_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));  // NOLINT: zlib's API
    stream_.avail_in = static_cast<uInt>(data.size());
    while (ok_ && stream_.avail_in > 0) {
      stream_.next_out = scratch_.data();
      stream_.avail_out = static_cast<uInt>(scratch_.size());
      const int status = inflate(&stream_, Z_NO_FLUSH);
      produced_ += scratch_.size() - stream_.avail_out;
      if (status != Z_OK) ok_ = false;  // the end, or data the decoder will judge
      if (produced_ > limit_) return;
    }
  }

  void setLimit(std::uint64_t limit) { limit_ = limit; }
  bool overLimit() const { return produced_ > limit_; }

 private:
  z_stream stream_{};
  std::array<Bytef, 1 << 16> scratch_{};
  std::uint64_t produced_ = 0;
  std::uint64_t limit_ = 0;
  bool ok_ = false;
};

}  // namespace

void checkPngData(std::string_view bytes, const std::string& source) {
  if (bytes.substr(0, kPngSignature.size()) != kPngSignature) return;
  const auto fail = [&](const std::string& what) {
    throw InputError("'" + source + "': not a readable PNG image: " + what);
  };
  std::optional<std::uint64_t> expected;  // filtered bytes the header declares
  InflateCounter inflated;
  std::size_t at = kPngSignature.size();
  while (at + 12 <= bytes.size()) {
    const std::uint64_t length = bigEndian32(bytes, at);
    const std::string_view type = bytes.substr(at + 4, 4);
    if (length > bytes.size() - at - 12)
      fail("chunk '" + std::string(type) + "' at byte " + std::to_string(at) + " declares " + std::to_string(length) +
           " bytes, past the end of the file (" + std::to_string(bytes.size()) + " bytes)");
    const std::string_view data = bytes.substr(at + 8, length);
    if (type == "IHDR" && length >= 13 && !expected) {
      constexpr std::array<std::uint64_t, 7> kChannels{1, 0, 3, 1, 2, 0, 4};  // by colour type
      const std::uint64_t colourType = static_cast<unsigned char>(data[9]);
      const std::uint64_t channels = colourType < kChannels.size() ? kChannels[colourType] : 4;
      const std::uint64_t depth = static_cast<unsigned char>(data[8]);
      expected = filteredBytes(bigEndian32(data, 0), bigEndian32(data, 4), std::max<std::uint64_t>(channels, 1) * depth,
                               data[12] != 0);
      inflated.setLimit(*expected);
    } else if (type == "IDAT" && expected) {
      inflated.feed(data);
      if (inflated.overLimit())
        fail("its image data inflates to more than the " + std::to_string(*expected) +
             " bytes its header declares (damaged or crafted)");
    } else if (type == "IEND") {
      break;
    }
    at += 12 + length;
  }
}

}  // namespace isovdb::io
