// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file reservoir_mc.cc
/// @brief `isovdb-reservoir-mc`: the Marching Cubes stage of `isovdb reservoir` alone,
///        repeated in one process on a deck read once (a small deck such as Reek's takes
///        milliseconds, less than the noise of whole runs). Prints one JSON line: cells,
///        cut cells, triangles, and the median and best seconds of the repeats.
///
///   isovdb-reservoir-mc DECK.grdecl [MORE.grdecl...] --property PORO --iso 0.2
///                       [--repeats 50] [--threads N]
#include <tbb/global_control.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "isovdb/reservoir/corner_point_grid.h"
#include "isovdb/reservoir/grdecl_reader.h"
#include "isovdb/reservoir/hex_marching_cubes.h"

int main(int argc, char** argv) {
  CLI::App app{"Marching Cubes on a corner-point grid, repeated in one process"};
  std::vector<std::filesystem::path> decks;
  std::string property = "PORO";
  double iso = 0.2;
  int repeats = 50, threads = 0;
  app.add_option("decks", decks, "GRDECL files")->required()->check(CLI::ExistingFile);
  app.add_option("--property", property, "cell property to contour");
  app.add_option("--iso", iso, "iso-value");
  app.add_option("--repeats", repeats, "runs of the stage")->check(CLI::PositiveNumber);
  app.add_option("--threads", threads, "worker threads (0: all cores)")->check(CLI::NonNegativeNumber);
  CLI11_PARSE(app, argc, argv);
  std::optional<tbb::global_control> control;
  if (threads > 0) control.emplace(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  using namespace isovdb::reservoir;
  const GrdeclDeck deck = readGrdecl(decks);
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  const CornerField field = averageToCorners(grid, deck, property);
  std::vector<double> seconds;
  HexContourResult result;
  for (int run = 0; run < repeats; ++run) {
    const auto start = std::chrono::steady_clock::now();
    result = contourHexahedra(grid, field, {.iso = iso});
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  const double first = seconds.front();  // the only run of `isovdb reservoir`: fresh memory
  std::sort(seconds.begin(), seconds.end());
  const auto usable = std::count(field.usable.begin(), field.usable.end(), 1);
  std::printf(
      "{\"cells\": %zu, \"cut_cells\": %lld, \"triangles\": %zu, \"median_s\": %.6f, \"best_s\": %.6f, \"first_s\": "
      "%.6f, "
      "\"m_cells_per_s\": %.2f}\n",
      static_cast<std::size_t>(usable), static_cast<long long>(result.cutCells), result.mesh.triangleCount(),
      seconds[seconds.size() / 2], seconds.front(), first,
      static_cast<double>(usable) / seconds[seconds.size() / 2] * 1e-6);
}
