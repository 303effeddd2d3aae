// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/raw_reader.h"

#include <cmath>
#include <limits>

#include "isovdb/errors.h"
#include "isovdb/io/byte_stream.h"
#include "isovdb/io/dense_slice_stream.h"

namespace isovdb::io {

std::unique_ptr<SliceStream> openRaw(const std::filesystem::path& path, const RawOptions& options) {
  const std::string source = path.string();
  const std::string where = "'" + source + "': ";
  VolumeHeader header;
  header.dims = options.dims;
  header.sampleType = options.type;
  header.bigEndian = options.bigEndian;
  header.spacing = options.spacing;
  const std::int64_t dataBytes = checkedVolumeBytes(header, source, "dims");
  for (int axis = 0; axis < 3; ++axis) {
    if (!std::isfinite(options.spacing[axis]) || options.spacing[axis] <= 0)
      throw InputError(where + "spacing: each value must be finite and positive, got " +
                       std::to_string(options.spacing[axis]) + " for axis " + "xyz"[axis]);
  }
  if (options.headerBytes < 0)
    throw InputError(where + "header bytes must be >= 0, got " + std::to_string(options.headerBytes));

  auto bytes = std::make_unique<FileRegionStream>(path, FileRegionOptions{});
  const std::int64_t fileSize = bytes->fileSize();
  const std::string need = std::to_string(options.headerBytes) + " header bytes + " + std::to_string(options.dims[0]) +
                           " x " + std::to_string(options.dims[1]) + " x " + std::to_string(options.dims[2]) + " " +
                           std::string(sampleTypeName(options.type)) + " samples = ";
  if (dataBytes > std::numeric_limits<std::int64_t>::max() - options.headerBytes ||
      fileSize != options.headerBytes + dataBytes) {
    const std::string expected = dataBytes > std::numeric_limits<std::int64_t>::max() - options.headerBytes
                                     ? "more than 2^63"
                                     : std::to_string(options.headerBytes + dataBytes);
    throw InputError(where + "file size is " + std::to_string(fileSize) + " bytes but " + need + expected +
                     " bytes (check dims, type and header bytes)");
  }
  bytes->skip(options.headerBytes);
  return std::make_unique<DenseSliceStream>(source, header, std::move(bytes));
}

}  // namespace isovdb::io
