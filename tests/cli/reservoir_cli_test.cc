// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// `isovdb reservoir` end to end: a shared sample with tessellation and statistics, and a bad deck.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <stb_image.h>

#include "isovdb/mesh/preview.h"

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

TEST(CliReservoir, MapAxesAreStatedInEveryMeshHeader) {
  // Two cells, PORO 0 and 1; MAPAXES as Reek's. The mesh stays in grid coordinates (float
  // positions near 6e6 would round to 0.5 m); the axes go into the file's header.
  TempDir dir;
  std::string deck = "MAPAXES\n456510.625 5938935.5 456510.625 5926880.172 467216.753 5926880.172 /\n";
  deck += "SPECGRID\n2 1 1 1 F /\nCOORD\n";
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i)
      deck +=
          std::to_string(i) + " " + std::to_string(j) + " 0 " + std::to_string(i) + " " + std::to_string(j) + " 1\n";
  deck += "/\nZCORN\n8*0 8*1 /\nPORO\n0 1 /\n";
  writeFile(dir / "two.grdecl", deck);
  const std::string axes = "mapaxes 456510.625 5938935.5 456510.625 5926880.172 467216.753 5926880.172 (Eclipse";
  for (const std::string name : {"m.ply", "m.obj", "m.glb"}) {
    std::string output;
    ASSERT_EQ(runCommand(cliPath().string() + " -q reservoir " + (dir / "two.grdecl").string() +
                             " --property PORO --iso 0.3 -o " + (dir / name).string(),
                         &output),
              0)
        << output;
    const std::string file = readFile(dir / name);
    const std::string head = file.substr(0, file.find(name == "m.obj" ? "\nv " : "end_header"));
    EXPECT_NE(head.find(axes), std::string::npos) << name << ": " << head.substr(0, 400);
    EXPECT_NE(head.find("PORO = 0.3 of two.grdecl"), std::string::npos) << name;
  }
  // The PLY stays readable: its comment lines are skipped by readers (ours too). The
  // surface ends where the two cells do, so check's verdict is "not closed" (exit 1).
  std::string output;
  EXPECT_EQ(runCommand(cliPath().string() + " check " + (dir / "m.ply").string(), &output), 1) << output;
  EXPECT_NE(output.find("mesh: NOT closed, manifold"), std::string::npos) << output;
}

TEST(CliReservoir, ThreadsDoNotChangeTheBytes) {
  // SPE9's 9,000 cells are nine blocks of Marching Cubes, merged in order whatever thread
  // made each.
  const auto deck = dataDir() / "reservoir/spe9/SPE9_CP.DATA";
  TempDir dir;
  std::string output;
  for (const std::string threads : {"1", "2", "0"})
    ASSERT_EQ(runCommand(cliPath().string() + " -q reservoir " + deck.string() + " --property PERMX --iso 100 -o " +
                             (dir / ("t" + threads + ".ply")).string() + " --threads " + threads,
                         &output),
              0)
        << output;
  EXPECT_EQ(readFile(dir / "t1.ply"), readFile(dir / "t2.ply"));
  EXPECT_EQ(readFile(dir / "t1.ply"), readFile(dir / "t0.ply"));
  EXPECT_EQ(runCommand(cliPath().string() + " -q reservoir " + deck.string() + " --property PERMX --iso 100 -o " +
                           (dir / "bad.ply").string() + " --threads -1",
                       &output),
            2);
  EXPECT_NE(output.find("--threads: expected 0 (every core) or more, got -1"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.ply"));
}

TEST(CliReservoir, CheckAndPreviewAsInExtract) {
  // --check: an open sheet passes when manifold and free of self-intersections (a reservoir
  // surface ends at the grid's border and inactive cells); --preview draws it.
  const auto deck = dataDir() / "reservoir/spe9/SPE9_CP.DATA";
  TempDir dir;
  const auto png = dir / "spe9.png";
  std::string output;
  ASSERT_EQ(runCommand(cliPath().string() + " -q reservoir " + deck.string() + " --property PERMX --iso 100 -o " +
                           (dir / "k.ply").string() + " --check --preview " + png.string() + " --stats " +
                           (dir / "k.json").string(),
                       &output),
            0)
      << output;
  const auto stats = nlohmann::json::parse(readFile(dir / "k.json"));
  EXPECT_EQ(stats["check"]["self_intersecting_pairs"], 0);
  EXPECT_EQ(stats["reservoir"]["self_intersecting_pairs"]["total"], 0);
  EXPECT_EQ(stats["check"]["manifold"], true);
  EXPECT_EQ(stats["passed"], true);
  EXPECT_NE(output.find("preview: " + png.string()), std::string::npos) << output;
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(png.c_str(), &width, &height, &channels, 3);
  ASSERT_NE(pixels, nullptr);
  std::size_t object = 0;
  for (int i = 0; i < width * height; ++i) object += pixels[3 * i] != mesh::kPreviewBackground;
  stbi_image_free(pixels);
  EXPECT_GT(object, std::size_t(width * height / 20));
  EXPECT_EQ(runCommand(cliPath().string() + " -q reservoir " + deck.string() + " --property PERMX --iso 100 -o " +
                           (dir / "u.ply").string() + " --preview " + (dir / "spe9.jpg").string(),
                       &output),
            2);
  EXPECT_NE(output.find("--preview writes a .png"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(dir / "u.ply"));
  // Reek PORO 0.21 as contoured had 29 self-intersecting pairs: 20 at pinch-outs (cells of
  // zero thickness at some pillars, until their top and bottom corners became one point)
  // and 6 more between thin twisted cells, which the untangling fans again. It passes.
  const auto reek = sharedDataDir() / "reservoir/reek";
  if (!std::filesystem::exists(reek)) GTEST_SKIP() << "no " << reek;
  const std::string reekRun = cliPath().string() + " -q reservoir " + (reek / "reek_sim_grid.grdecl").string() + " " +
                              (reek / "reek_sim_poro.grdecl").string() + " --property PORO --iso 0.21 --check";
  EXPECT_EQ(runCommand(reekRun + " -o " + (dir / "r.ply").string() + " --stats " + (dir / "r.json").string(), &output),
            0)
      << output;
  EXPECT_NE(output.find("passed: yes"), std::string::npos) << output;
  const auto reek21 = nlohmann::json::parse(readFile(dir / "r.json"));
  const auto& untangle = reek21["reservoir"]["untangle"];
  EXPECT_EQ(untangle["pairs_before"], 6);
  EXPECT_EQ(untangle["pairs_after"], 0);
  EXPECT_GE(untangle["loops_refanned"].get<int>(), 1);
  // The pairs that remain, told apart by the cells that made them (none here).
  const auto& pairs = reek21["reservoir"]["self_intersecting_pairs"];
  EXPECT_EQ(pairs["total"], reek21["check"]["self_intersecting_pairs"]);
  EXPECT_EQ(pairs["total"], 0);
  EXPECT_EQ(reek21["reservoir"]["pinched_cells"], 20);
  EXPECT_EQ(
      pairs["at_inverted_cells"].get<int>() + pairs["at_pinched_cells"].get<int>() + pairs["elsewhere"].get<int>(),
      pairs["total"].get<int>());
  // PN triangles bulge by more than Reek's 3 m layers over its 100 m triangles; where the
  // curved sheets crossed (11,792 pairs here), their edges are kept straight.
  EXPECT_EQ(runCommand(reekRun + " --tessellate max=3 -o " + (dir / "t.ply").string() + " --stats " +
                           (dir / "t.json").string(),
                       &output),
            0)
      << output;
  const auto pn = nlohmann::json::parse(readFile(dir / "t.json"));
  EXPECT_GT(pn["reservoir"]["tessellation_straightened"]["pairs_before"].get<int>(), 1000);
  EXPECT_EQ(pn["reservoir"]["tessellation_straightened"]["pairs_after"], 0);
  EXPECT_EQ(pn["check"]["self_intersecting_pairs"], 0);
  // A mesh that fails the check is written, and the run exits 1: cells whose depths fold
  // them over each other (random ZCORN; 10 of the 12 cells inverted) give a pair that no
  // fan undoes, counted at inverted cells.
  writeFile(dir / "folded.grdecl",
            "SPECGRID\n 2 2 3 1 F /\nCOORD\n0 0 0 0 0 10\n10 0 0 10 0 10\n20 0 0 20 0 10\n0 10 0 0 10 10\n"
            "10 10 0 10 10 10\n20 10 0 20 10 10\n0 20 0 0 20 10\n10 20 0 10 20 10\n20 20 0 20 20 10\n/\n"
            "ZCORN\n0 0 3 -3 -3 -3 0 -3 0 -3 -3 3 3 -3 0 -3 5 -1 -1 2 -1 5 -1 2 -1 2 2 5 2 -1 2 2\n"
            "-1 2 2 -1 -1 -1 2 5 5 2 5 5 2 2 2 2 4 1 4 7 4 7 4 1 1 7 4 4 4 7 7 1\n"
            "1 4 4 4 7 7 1 1 4 7 1 1 4 7 4 7 6 3 9 6 6 3 9 3 6 6 6 6 9 9 9 3\n/\n"
            "PORO\n2 7 6 8 4 2 6 8 4 6 5 6 /\n");
  EXPECT_EQ(runCommand(cliPath().string() + " -q reservoir " + (dir / "folded.grdecl").string() +
                           " --property PORO --iso 4.5 --check -o " + (dir / "f.ply").string() + " --stats " +
                           (dir / "f.json").string(),
                       &output),
            1)
      << output;
  EXPECT_NE(output.find("passed: NO"), std::string::npos) << output;
  EXPECT_TRUE(std::filesystem::exists(dir / "f.ply"));
  const auto folded = nlohmann::json::parse(readFile(dir / "f.json"));
  EXPECT_GT(folded["reservoir"]["inverted_cells"].get<int>(), 0);
  EXPECT_GT(folded["reservoir"]["self_intersecting_pairs"]["at_inverted_cells"].get<int>(), 0);
  EXPECT_EQ(folded["reservoir"]["self_intersecting_pairs"]["total"], folded["check"]["self_intersecting_pairs"]);
  EXPECT_NE(output.find("self-intersecting pairs: "), std::string::npos) << output;
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
