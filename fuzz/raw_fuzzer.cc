// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// libFuzzer harness of the raw reader. The first four bytes are the options a user
// would pass (--type and byte order, --dims up to 16 per axis) and also the file's
// header (--header-bytes 4), so the size check sees both matching and mismatched files.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isovdb/pipeline/load_volume.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  isovdb::io::RawOptions raw;
  raw.type = static_cast<isovdb::io::SampleType>(data[0] % 8);
  raw.bigEndian = (data[0] & 8) != 0;
  for (int a = 0; a < 3; ++a) raw.dims[a] = 1 + data[1 + a] % 16;
  raw.headerBytes = 4;
  const auto path = isovdb::fuzz::writeInput(data, size, ".raw");
  isovdb::pipeline::InputOptions options;
  options.raw = raw;
  options.denseAs = (data[0] & 16) != 0 ? isovdb::pipeline::DenseAs::Scalar : isovdb::pipeline::DenseAs::Mask;
  isovdb::fuzz::expectCleanOutcome([&] { isovdb::pipeline::loadVolume(path, options); });
  return 0;
}
