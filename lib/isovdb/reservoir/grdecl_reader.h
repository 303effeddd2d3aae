// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file grdecl_reader.h
/// @brief Reads an Eclipse GRDECL grid deck (SPECGRID/DIMENS, COORD, ZCORN,
/// ACTNUM, MAPAXES and any numeric cell property such as PORO or PERMX).
///
/// Supported syntax: `n*value` repeats, `--` comments, quoted strings,
/// `INCLUDE 'file' /` relative to the including file, `/` record terminators.
/// Section keywords and flags without data (RUNSPEC, GRID, OIL, ECHO, ...) are
/// accepted; reading stops at the first section after GRID/EDIT (PROPS, ...).
/// Section keywords: FAULTS and MULTFLT are read (faults do not change the cells'
/// geometry: a corner-point grid's faults are already in its ZCORN); EQUALS, COPY,
/// MULTIPLY, ADD, MINVALUE and MAXVALUE are applied in order, on their box or the
/// current BOX (grdecl_edits.h), and an array read inside a BOX fills that box.
/// A keyword whose records are not numeric and that the reader does not know is
/// skipped with a warning, up to its empty record when it has several.
/// Counts are validated by the grid model (corner_point_grid.h).
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace isovdb::reservoir {

/// One record of FAULTS: a named fault's cell faces.
struct GrdeclFault {
  std::string name;
  std::array<int, 6> box{};  ///< I1 I2 J1 J2 K1 K2, 1-based as in the file
  std::string face;          ///< X, X-, Y, Y-, Z, Z- (I, J, K accepted)
};

struct GrdeclDeck {
  std::filesystem::path path;                             ///< the file that was read (for messages)
  std::array<int, 3> dims{0, 0, 0};                       ///< SPECGRID or DIMENS: nx, ny, nz
  std::vector<double> coord;                              ///< 6 values per pillar, (nx+1)(ny+1) pillars
  std::vector<double> zcorn;                              ///< 8 values per cell
  std::vector<double> actnum;                             ///< empty (all active) or one per cell
  std::vector<double> mapaxes;                            ///< empty or 6 values (not applied)
  std::map<std::string, std::vector<double>> properties;  ///< other numeric keywords
  std::vector<std::string> warnings;                      ///< one line each, naming file and line
  std::vector<GrdeclFault> faults;                        ///< FAULTS records (geometry is not changed by them)
  std::map<std::string, double> faultMultipliers;         ///< MULTFLT: transmissibility multiplier per fault
  int editsApplied = 0;                                   ///< EQUALS/COPY/MULTIPLY/ADD/MINVALUE/MAXVALUE records
};

/// Guards against hostile sizes, so that a few bytes (`1000000000*0`) cannot ask for gigabytes.
struct GrdeclLimits {
  /// Most values the deck's keywords may hold together, `n*value` repeats counted: 2.5 x 10^8
  /// doubles are 2 GB, a grid of 25 million cells with ZCORN, ACTNUM and a property. A
  /// SPECGRID/DIMENS whose ZCORN (8 N) would not fit is refused, and each array is bounded
  /// by the grid too: 8 N (ZCORN) or 6 (NX+1)(NY+1) (COORD) values.
  long long maxValues = 250'000'000;
};

/// Reads `path` and its INCLUDEs. @throw InputError naming the file and line
/// (missing `/`, a malformed number, an unreadable INCLUDE, a keyword beyond `limits`);
/// @throw IoError when `path` cannot be read.
GrdeclDeck readGrdecl(const std::filesystem::path& path, const GrdeclLimits& limits = {});
/// Reads several files into one deck, in order (e.g. a grid file and a property file).
GrdeclDeck readGrdecl(const std::vector<std::filesystem::path>& paths, const GrdeclLimits& limits = {});

}  // namespace isovdb::reservoir
