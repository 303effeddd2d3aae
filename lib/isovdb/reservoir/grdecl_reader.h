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
/// A keyword whose record is not numeric and that the reader does not know is
/// skipped with a warning. Counts are validated by the grid model (corner_point_grid.h).
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace isovdb::reservoir {

struct GrdeclDeck {
  std::filesystem::path path;                             ///< the file that was read (for messages)
  std::array<int, 3> dims{0, 0, 0};                       ///< SPECGRID or DIMENS: nx, ny, nz
  std::vector<double> coord;                              ///< 6 values per pillar, (nx+1)(ny+1) pillars
  std::vector<double> zcorn;                              ///< 8 values per cell
  std::vector<double> actnum;                             ///< empty (all active) or one per cell
  std::vector<double> mapaxes;                            ///< empty or 6 values (not applied)
  std::map<std::string, std::vector<double>> properties;  ///< other numeric keywords
  std::vector<std::string> warnings;                      ///< one line each, naming file and line
};

/// Reads `path` and its INCLUDEs. @throw InputError naming the file and line
/// (missing `/`, a malformed number, an unreadable INCLUDE); @throw IoError when `path` cannot be read.
GrdeclDeck readGrdecl(const std::filesystem::path& path);
/// Reads several files into one deck, in order (e.g. a grid file and a property file).
GrdeclDeck readGrdecl(const std::vector<std::filesystem::path>& paths);

}  // namespace isovdb::reservoir
