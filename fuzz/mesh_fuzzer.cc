// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// libFuzzer harness of one mesh reader, through readMesh as `isovdb check` and `compare`
// call it, then the mesh checks `check` runs on what it read: the input is written as a
// file with the extension ISOVDB_FUZZ_EXTENSION (.ply, .obj, .stl, .glb or .gltf;
// fuzz/CMakeLists.txt builds one harness per extension).
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isovdb/io/mesh_file.h"
#include "isovdb/mesh/validate.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = isovdb::fuzz::writeInput(data, size, ISOVDB_FUZZ_EXTENSION);
  isovdb::fuzz::expectCleanOutcome([&] { isovdb::mesh::validateMesh(isovdb::io::readMesh(path)); });
  return 0;
}
