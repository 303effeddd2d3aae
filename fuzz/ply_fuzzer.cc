// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// libFuzzer harness of the PLY reader (ASCII and binary), then the mesh checks
// `isovdb check` runs on what it read.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isovdb/io/ply.h"
#include "isovdb/mesh/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = isovdb::fuzz::writeInput(data, size, ".ply");
  isovdb::fuzz::expectCleanOutcome([&] { isovdb::mesh::validateMesh(isovdb::io::readPly(path)); });
  return 0;
}
