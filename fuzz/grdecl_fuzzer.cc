// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// libFuzzer harness of the GRDECL reader and the corner-point grid built from a deck,
// as `isovdb reservoir` reads one.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isovdb/reservoir/corner_point_grid.h"
#include "isovdb/reservoir/grdecl_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = isovdb::fuzz::writeInput(data, size, ".grdecl");
  isovdb::fuzz::expectCleanOutcome([&] {
    // The user's --max-values default (2.5 x 10^8 values, 2 GB) is beyond the harness's 2 GB RSS
    // limit: a smaller one tests the same bound.
    const isovdb::reservoir::GrdeclDeck deck = isovdb::reservoir::readGrdecl(path, {.maxValues = 10'000'000});
    isovdb::reservoir::buildCornerPointGrid(deck);
  });
  return 0;
}
