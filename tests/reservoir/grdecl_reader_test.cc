// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// GRDECL reader and grid model: syntax, bad input, the three shared samples.
#include <gtest/gtest.h>

#include <cmath>

#include "isovdb/errors.h"
#include "isovdb/reservoir/corner_point_grid.h"
#include "isovdb/reservoir/grdecl_reader.h"
#include "reservoir/grdecl_writer.h"
#include "support/test_support.h"

namespace isovdb::reservoir {
namespace {

using test::TempDir;
using test::writeFile;

// A 2x1x1 grid: the smallest deck with every keyword.
const char* kTiny =
    "SPECGRID\n 2 1 1 1 F /\n"
    "COORD\n 0 0 0 0 0 1  1 0 0 1 0 1  2 0 0 2 0 1\n 0 1 0 0 1 1  1 1 0 1 1 1  2 1 0 2 1 1 /\n"
    "ZCORN\n 8*0 8*1 /\n"
    "ACTNUM\n 2*1 /\n";

std::string errorOf(const std::filesystem::path& path) {
  try {
    buildCornerPointGrid(readGrdecl(path));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GrdeclReader, RepeatsCommentsIncludeAndTerminators) {
  TempDir dir;
  writeFile(dir / "prop.inc", "PORO -- porosity\n 0.25 3e-1/\n");
  writeFile(dir / "deck.grdecl", std::string("RUNSPEC\nTITLE\n my title\nGRID\n-- a comment\n") + kTiny +
                                     "INCLUDE\n 'prop.inc' /\nECHO\nPROPS\nGARBAGE after the grid\n");
  const GrdeclDeck deck = readGrdecl(dir / "deck.grdecl");
  EXPECT_EQ(deck.dims, (std::array<int, 3>{2, 1, 1}));
  ASSERT_EQ(deck.zcorn.size(), 16u);
  EXPECT_EQ(deck.zcorn[7], 0.0);
  EXPECT_EQ(deck.zcorn[8], 1.0);
  ASSERT_EQ(deck.properties.at("PORO").size(), 2u);
  EXPECT_DOUBLE_EQ(deck.properties.at("PORO")[1], 0.3);
  EXPECT_TRUE(deck.warnings.empty());
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  EXPECT_EQ(grid.activeCells, 2);
  // The two cells share the four corners of their common face.
  EXPECT_EQ(grid.pointIds[0][1], grid.pointIds[1][0]);
  EXPECT_EQ(grid.pointIds[0][7], grid.pointIds[1][6]);
  EXPECT_EQ(grid.points.size(), 12u);
  EXPECT_EQ(grid.invertedCells, 0);
}

TEST(GrdeclReader, UnknownKeywordIsSkippedWithAWarning) {
  TempDir dir;
  writeFile(dir / "deck.grdecl", std::string("FOOBAR\n 'text' 3 /\n") + kTiny);
  const GrdeclDeck deck = readGrdecl(dir / "deck.grdecl");
  ASSERT_EQ(deck.warnings.size(), 1u);
  EXPECT_NE(deck.warnings[0].find("unknown keyword FOOBAR"), std::string::npos);
  EXPECT_NE(deck.warnings[0].find("deck.grdecl:1"), std::string::npos);
  EXPECT_EQ(buildCornerPointGrid(deck).activeCells, 2);
}

TEST(GrdeclReader, BoxEditsAreAppliedInTheDecksOrder) {
  // A 3x2x2 grid (12 cells, index i + 3 (j + 2 k)).
  TempDir dir;
  writeFile(dir / "deck.grdecl",
            "SPECGRID\n 3 2 2 1 F /\n"
            "PORO\n 12*0.1 /\n"
            "EQUALS\n 'PORO' 0.3 2 3 1 1 1 1 /\n"  // cells 1, 2
            "  PERMX 50 /\n"                       // a new property, every cell
            "/\n"
            "BOX\n 1 1 1 2 2 2 /\n"         // cells 6, 9
            "NTG\n 0.7 0.8 /\n"             // an array inside a box fills the box
            "MULTIPLY\n 'PERMX' 2 /\n /\n"  // within the current BOX
            "ENDBOX\n"
            "COPY\n 'PORO' 'SWL' 1* 1* 2 2 1* 1* /\n /\n"  // j = 2: cells 3-5, 9-11
            "ADD\n 'PORO' 0.05 3 3 2 2 2 2 /\n /\n"        // cell 11
            "MAXVALUE\n 'PERMX' 60 /\n /\n"
            "MINVALUE\n 'PORO' 0.12 1 1 1 1 1 1 /\n /\n"  // cell 0
            "MULTREGT\n 1 2 0.5 /\n /\n"                  // not about cells: skipped, named
            "FAULTS\n 'F1' 1 1 1 2 1 2 'X' /\n 'F1' 2 2 1 1 1 2 'Y-' /\n 'F2' 3 3 1 2 1 1 'Z' /\n /\n"
            "MULTFLT\n 'F1' 0.1 /\n F2 0 /\n /\n");
  const GrdeclDeck deck = readGrdecl(dir / "deck.grdecl");
  const auto& poro = deck.properties.at("PORO");
  EXPECT_DOUBLE_EQ(poro[0], 0.12);
  EXPECT_DOUBLE_EQ(poro[1], 0.3);
  EXPECT_DOUBLE_EQ(poro[2], 0.3);
  EXPECT_DOUBLE_EQ(poro[11], 0.15);
  EXPECT_DOUBLE_EQ(poro[10], 0.1);
  const auto& permx = deck.properties.at("PERMX");
  EXPECT_EQ(permx[0], 50.0);
  EXPECT_EQ(permx[6], 60.0);  // 50 * 2 in the box, then at most 60
  EXPECT_EQ(permx[9], 60.0);
  const auto& ntg = deck.properties.at("NTG");
  EXPECT_EQ(ntg[6], 0.7);
  EXPECT_EQ(ntg[9], 0.8);
  EXPECT_EQ(ntg[0], 0.0);
  const auto& swl = deck.properties.at("SWL");
  EXPECT_DOUBLE_EQ(swl[3], 0.1);
  EXPECT_EQ(swl[0], 0.0);
  EXPECT_EQ(deck.editsApplied, 7);
  ASSERT_EQ(deck.faults.size(), 3u);
  EXPECT_EQ(deck.faults[1].name, "F1");
  EXPECT_EQ(deck.faults[1].box, (std::array<int, 6>{2, 2, 1, 1, 1, 2}));
  EXPECT_EQ(deck.faults[1].face, "Y-");
  EXPECT_EQ(deck.faultMultipliers.at("F1"), 0.1);
  EXPECT_EQ(deck.faultMultipliers.at("F2"), 0.0);
  ASSERT_EQ(deck.warnings.size(), 1u);
  EXPECT_NE(deck.warnings[0].find("MULTREGT"), std::string::npos);
}

TEST(GrdeclReader, EditsThatCannotApplySayWhy) {
  TempDir dir;
  writeFile(dir / "early.grdecl", "EQUALS\n 'PORO' 0.3 /\n /\n");
  EXPECT_THROW(
      {
        try {
          readGrdecl(dir / "early.grdecl");
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("before SPECGRID or DIMENS"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
  writeFile(dir / "box.grdecl", "SPECGRID\n 3 2 2 1 F /\nEQUALS\n 'PORO' 0.3 1 4 1 1 1 1 /\n /\n");
  try {
    readGrdecl(dir / "box.grdecl");
    ADD_FAILURE() << "a box beyond the grid was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("box.grdecl:3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("I2 = 4 outside 1..3"), std::string::npos) << e.what();
  }
  writeFile(dir / "missing.grdecl", "SPECGRID\n 3 2 2 1 F /\nMULTIPLY\n 'PERMZ' 0.1 /\n /\n");
  const GrdeclDeck deck = readGrdecl(dir / "missing.grdecl");
  ASSERT_EQ(deck.warnings.size(), 1u);
  EXPECT_NE(deck.warnings[0].find("MULTIPLY of PERMZ, which has no value per cell yet"), std::string::npos);
}

TEST(GrdeclReader, FaultDecksOfOtherProjectsLoad) {
  // ResInsight's TestModels/fault_test: FAULTS in the deck and in two levels of INCLUDE.
  const GrdeclDeck deck = readGrdecl(test::dataDir() / "reservoir/fault_test/regular27cell.DATA");
  EXPECT_EQ(deck.dims, (std::array<int, 3>{3, 3, 3}));
  EXPECT_EQ(deck.faults.size(), 10u);
  EXPECT_EQ(deck.faults.front().name, "grid_C202");  // the innermost INCLUDE comes first
  EXPECT_EQ(deck.faults.back().name, "DATA_FILE_MAIN");
  EXPECT_TRUE(deck.warnings.empty());
  EXPECT_EQ(buildCornerPointGrid(deck).activeCells, 27);
  // resdata's test-data/local/ECLIPSE/FAULTS/fault1.grdecl: 73 records of three faults.
  const GrdeclDeck faults = readGrdecl(test::dataDir() / "reservoir/fault_test/fault1.grdecl");
  ASSERT_EQ(faults.faults.size(), 73u);
  EXPECT_EQ(faults.faults[72].name, "F3");
  EXPECT_EQ(faults.faults[72].box, (std::array<int, 6>{130, 130, 32, 32, 1, 43}));
}

TEST(GrdeclReader, CountsNotMatchingSpecgridNameTheFileAndKeyword) {
  TempDir dir;
  std::string zcornShort = kTiny;
  zcornShort.replace(zcornShort.find("8*1"), 3, "7*1");
  writeFile(dir / "z.grdecl", zcornShort);
  const std::string z = errorOf(dir / "z.grdecl");
  EXPECT_NE(z.find("z.grdecl"), std::string::npos) << z;
  EXPECT_NE(z.find("ZCORN has 15 values, expected 16"), std::string::npos) << z;

  std::string coordLong = kTiny;
  coordLong.replace(coordLong.find(" /\nZCORN"), 3, " 9 /");
  writeFile(dir / "c.grdecl", coordLong);
  const std::string c = errorOf(dir / "c.grdecl");
  EXPECT_NE(c.find("COORD has 37 values, expected 36"), std::string::npos) << c;

  std::string act = kTiny;
  act.replace(act.find("2*1"), 3, "3*1");
  writeFile(dir / "a.grdecl", act);
  EXPECT_NE(errorOf(dir / "a.grdecl").find("ACTNUM has 3 values, expected 2"), std::string::npos);
}

TEST(GrdeclReader, MissingTerminatorIsAnError) {
  TempDir dir;
  std::string deck = kTiny;
  deck.replace(deck.find("8*1 /"), 5, "8*1");  // ZCORN runs into ACTNUM
  writeFile(dir / "m.grdecl", deck);
  const std::string e = errorOf(dir / "m.grdecl");
  EXPECT_NE(e.find("m.grdecl"), std::string::npos) << e;
  EXPECT_NE(e.find("ZCORN has no terminating '/'"), std::string::npos) << e;

  writeFile(dir / "eof.grdecl", std::string(kTiny) + "PORO\n 1 2\n");
  EXPECT_NE(errorOf(dir / "eof.grdecl").find("PORO has no terminating '/' before the end"), std::string::npos);

  writeFile(dir / "bad.grdecl", std::string(kTiny) + "PORO\n 1 x2 /\n");
  EXPECT_NE(errorOf(dir / "bad.grdecl").find("'x2' is not a number"), std::string::npos);
}

TEST(GrdeclReader, PropertyShorterThanTheCellsIsAnError) {
  TempDir dir;
  writeFile(dir / "p.grdecl", std::string(kTiny) + "PORO\n 0.1 /\n");
  const GrdeclDeck deck = readGrdecl(dir / "p.grdecl");
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  try {
    averageToCorners(grid, deck, "PORO");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("p.grdecl: property PORO has 1 values, expected 2"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(averageToCorners(grid, deck, "PERMX"), InputError);
}

TEST(GrdeclReader, NanValues) {
  TempDir dir;
  std::string deck = kTiny;
  deck.replace(deck.find("8*0"), 3, "nan 7*0");
  writeFile(dir / "g.grdecl", deck);
  EXPECT_NE(errorOf(dir / "g.grdecl").find("ZCORN value 1 is not a finite number"), std::string::npos);

  writeFile(dir / "p.grdecl", std::string(kTiny) + "PORO\n nan 0.5 /\n");
  const GrdeclDeck d = readGrdecl(dir / "p.grdecl");
  const CornerPointGrid grid = buildCornerPointGrid(d);
  const CornerField field = averageToCorners(grid, d, "PORO");
  ASSERT_EQ(field.warnings.size(), 1u);
  EXPECT_NE(field.warnings[0].find("1 active cells have a NaN"), std::string::npos);
  EXPECT_FALSE(field.usable[0]);
  EXPECT_TRUE(field.usable[1]);
  // The shared corners take the value of the usable neighbour only.
  EXPECT_DOUBLE_EQ(field.value(grid, 0, 1), 0.5);
  EXPECT_TRUE(std::isnan(field.value(grid, 0, 0)));
}

/// kTiny's two cells with other ZCORN values (order: i fastest, bottom then top).
CornerPointGrid tinyGridWithZcorn(const std::string& zcorn) {
  TempDir dir;
  std::string deck = kTiny;
  deck.replace(deck.find("8*0 8*1"), 7, zcorn);
  writeFile(dir / "tiny.grdecl", deck);
  return buildCornerPointGrid(readGrdecl(dir / "tiny.grdecl"));
}

TEST(GrdeclReader, InvertedCellIsReported) {
  // Cell 0: bottom above top at its left corners.
  const CornerPointGrid grid = tinyGridWithZcorn("2 0 0 0 2 0 0 0 8*1");
  EXPECT_EQ(grid.invertedCells, 1);
  ASSERT_FALSE(grid.warnings.empty());
  EXPECT_NE(grid.warnings.back().find("inverted"), std::string::npos);
  EXPECT_NE(grid.warnings.back().find("(1,1,1)"), std::string::npos) << grid.warnings.back();
}

TEST(GrdeclReader, PinchedCellIsCountedNotInverted) {
  // Cell 0's top meets its bottom at one corner (a pinch-out): a zero Jacobian there.
  const CornerPointGrid grid = tinyGridWithZcorn("8*0 0 7*1");
  EXPECT_EQ(grid.pinchedCells, 1);
  EXPECT_EQ(grid.invertedCells, 0);
  EXPECT_EQ(tinyGridWithZcorn("8*0 8*1").pinchedCells, 0);
}

TEST(GrdeclReader, MissingFileAndMissingSpecgrid) {
  TempDir dir;
  EXPECT_THROW(readGrdecl(dir / "none.grdecl"), IoError);
  writeFile(dir / "n.grdecl", "PORO\n 1 /\n");
  EXPECT_NE(errorOf(dir / "n.grdecl").find("no SPECGRID"), std::string::npos);
  writeFile(dir / "i.grdecl", "INCLUDE\n 'nothere.inc' /\n");
  EXPECT_NE(errorOf(dir / "i.grdecl").find("INCLUDE file not found"), std::string::npos);
}

struct Sample {
  std::vector<std::string> files;
  std::array<int, 3> dims;
  std::int64_t active;
  std::string property;
};

TEST(GrdeclReader, BundledSpe9LoadsThroughInclude) {
  // SPE9_CP.DATA: RUNSPEC flags, TITLE, INCLUDE of the grid and of PERMX, PORO as 600*v repeats.
  const GrdeclDeck deck = readGrdecl(test::dataDir() / "reservoir/spe9/SPE9_CP.DATA");
  const CornerPointGrid grid = buildCornerPointGrid(deck);
  EXPECT_EQ(grid.dims, (std::array<int, 3>{24, 25, 15}));
  EXPECT_EQ(grid.activeCells, 9000);
  ASSERT_EQ(deck.properties.at("PORO").size(), 9000u);
  EXPECT_DOUBLE_EQ(deck.properties.at("PORO")[0], 0.087);
  EXPECT_DOUBLE_EQ(deck.properties.at("PORO")[8999], 0.157);
  EXPECT_EQ(deck.properties.at("PERMX").size(), 9000u);
  // PERMVALUES.DATA: COPY PERMX to PERMY and PERMZ, then MULTIPLY PERMZ by 0.01, applied in order.
  EXPECT_TRUE(deck.warnings.empty()) << deck.warnings.front();
  EXPECT_EQ(deck.editsApplied, 3);
  ASSERT_EQ(deck.properties.at("PERMY").size(), 9000u);
  ASSERT_EQ(deck.properties.at("PERMZ").size(), 9000u);
  for (const std::size_t c : {std::size_t{0}, std::size_t{4321}, std::size_t{8999}}) {
    EXPECT_EQ(deck.properties.at("PERMY")[c], deck.properties.at("PERMX")[c]);
    EXPECT_DOUBLE_EQ(deck.properties.at("PERMZ")[c], deck.properties.at("PERMX")[c] * 0.01);
  }
}

TEST(GrdeclReader, SharedSamplesLoad) {
  const auto root = test::sharedDataDir() / "reservoir";
  if (!std::filesystem::exists(root)) GTEST_SKIP() << "no " << root << " (shared reservoir samples)";
  const std::vector<Sample> samples = {
      {{"reek/reek_sim_grid.grdecl", "reek/reek_sim_poro.grdecl"}, {40, 64, 14}, 35838, "PORO"},
      {{"emerald/eme_small_w_hole_grid_params.grdecl"}, {21, 41, 18}, 7157, "FACIES"},
      {{"spe9/SPE9_CP.DATA"}, {24, 25, 15}, 9000, "PERMX"},
  };
  for (const Sample& s : samples) {
    std::vector<std::filesystem::path> paths;
    for (const auto& f : s.files) paths.push_back(root / f);
    const GrdeclDeck deck = readGrdecl(paths);
    const CornerPointGrid grid = buildCornerPointGrid(deck);
    EXPECT_EQ(grid.dims, s.dims) << s.files[0];
    EXPECT_EQ(grid.activeCells, s.active) << s.files[0];
    // Emerald has a few folded cells (warned about); the others none.
    EXPECT_LT(grid.invertedCells, grid.activeCells / 20) << s.files[0];
    std::cout << s.files[0] << ": " << grid.activeCells << " active cells, " << grid.invertedCells
              << " inverted, orientation " << grid.orientation << '\n';
    const CornerField field = averageToCorners(grid, deck, s.property);
    EXPECT_TRUE(deck.properties.count("PORO")) << s.files[0];
    for (const auto& w : deck.warnings) std::cout << "warning: " << w << '\n';
  }
}

}  // namespace
}  // namespace isovdb::reservoir
