// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// libFuzzer harness of one volume reader, through loadVolume as the CLI calls it: the
// input is written as a file with the extension ISOVDB_FUZZ_EXTENSION (.nrrd, .mha, .sgy
// or .vdb; fuzz/CMakeLists.txt builds one harness per extension).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isovdb/pipeline/load_volume.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = isovdb::fuzz::writeInput(data, size, ISOVDB_FUZZ_EXTENSION);
  isovdb::fuzz::expectCleanOutcome([&] { isovdb::pipeline::loadVolume(path, {}); });
  return 0;
}
