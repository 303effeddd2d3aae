// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb reservoir` end to end: a shared sample with tessellation and statistics, and a bad deck.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_support.h"

namespace isovdb::test {
namespace {

TEST(CliReservoir, Spe9PoroWithTessellationAndStatistics) {
  const auto deck = dataDir() / "reservoir/spe9/SPE9_CP.DATA";
  TempDir dir;
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q reservoir " + deck.string() +
                           " --property PORO --iso 0.1 --tessellate max=4 -o " + (dir / "s.ply").string() +
                           " --stats " + (dir / "s.json").string(),
                       &output),
            0)
      << output;
  const auto stats = nlohmann::json::parse(readFile(dir / "s.json"));
  EXPECT_EQ(stats["reservoir"]["active_cells"], 9000);
  EXPECT_GT(stats["reservoir"]["mc_triangles"].get<int>(), 0);
  EXPECT_GE(stats["reservoir"]["pn_triangles"].get<int>(), stats["reservoir"]["mc_triangles"].get<int>());
  EXPECT_EQ(stats["output"]["triangles"], stats["reservoir"]["pn_triangles"]);
  EXPECT_TRUE(std::filesystem::exists(dir / "s.ply"));
}

TEST(CliReservoir, BadDeckFailsNamingTheFile) {
  TempDir dir;
  writeFile(dir / "bad.grdecl", "SPECGRID\n 1 1 1 1 F /\nCOORD\n 24*0 /\nZCORN\n 7*0 /\nPORO\n 1 /\n");
  std::string output;
  EXPECT_EQ(runCommand(cliPath().string() + " -q reservoir " + (dir / "bad.grdecl").string() +
                           " --property PORO --iso 0.5 -o " + (dir / "o.ply").string(),
                       &output),
            2);
  EXPECT_NE(output.find("bad.grdecl: ZCORN has 7 values, expected 8"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(dir / "o.ply"));
}

}  // namespace
}  // namespace isovdb::test
