// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// libFuzzer harness of the GRDECL reader and the corner-point grid built from a deck,
// as `isovdb reservoir` reads one; small grids with a property are contoured and untangled.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isovdb/reservoir/corner_point_grid.h"
#include "isovdb/reservoir/grdecl_reader.h"
#include "isovdb/reservoir/hex_marching_cubes.h"
#include "isovdb/reservoir/untangle_loops.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = isovdb::fuzz::writeInput(data, size, ".grdecl");
  isovdb::fuzz::expectCleanOutcome([&] {
    // The user's --max-values default (2.5 x 10^8 values, 2 GB) is beyond the harness's 2 GB RSS
    // limit: a smaller one tests the same bound.
    const isovdb::reservoir::GrdeclDeck deck = isovdb::reservoir::readGrdecl(path, {.maxValues = 10'000'000});
    const isovdb::reservoir::CornerPointGrid grid = isovdb::reservoir::buildCornerPointGrid(deck);
    // Small grids with a property go on through Marching Cubes and the untangling, at the
    // mean of the property's finite values.
    if (deck.properties.empty() || grid.cellCount() > 50'000) return;
    const auto& [name, values] = *deck.properties.begin();
    double sum = 0;
    std::size_t finite = 0;
    for (const double v : values)
      if (std::isfinite(v)) {
        sum += v;
        ++finite;
      }
    if (finite == 0) return;
    const isovdb::reservoir::CornerField field = isovdb::reservoir::averageToCorners(grid, deck, name);
    isovdb::reservoir::HexContourResult contour = isovdb::reservoir::contourHexahedra(
        grid, field, {.iso = sum / static_cast<double>(finite), .triangleCells = true});
    isovdb::reservoir::untangleLoops(contour.mesh, contour.triangleCells);
  });
  return 0;
}
