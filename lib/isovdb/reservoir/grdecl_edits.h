// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file grdecl_edits.h
/// @brief The GRID/EDIT section keywords that change cell properties in a box of
///        cells, applied as the deck reads them (Eclipse's order): EQUALS, COPY,
///        MULTIPLY, ADD, MINVALUE, MAXVALUE, and BOX/ENDBOX, which also bound the
///        arrays read while a box is set.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace isovdb::reservoir {

/// Cells i1..i2, j1..j2, k1..k2, 0-based and inclusive.
struct CellBox {
  std::array<int, 3> lo{0, 0, 0}, hi{0, 0, 0};
  long long cellCount() const { return 1LL * (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1); }
};

/// The box of a record's six 1-based bounds; a missing (std::nullopt) bound takes
/// the default box's. @throw std::invalid_argument naming the bound out of the grid.
CellBox cellBoxOf(const std::array<std::optional<int>, 6>& bounds, const CellBox& defaults,
                  const std::array<int, 3>& dims);

/// Calls f(cell index) for every cell of `box` (index i + nx (j + ny k)), k slowest.
template <typename F>
void forEachCell(const CellBox& box, const std::array<int, 3>& dims, F&& f) {
  for (int k = box.lo[2]; k <= box.hi[2]; ++k)
    for (int j = box.lo[1]; j <= box.hi[1]; ++j)
      for (int i = box.lo[0]; i <= box.hi[0]; ++i)
        f(static_cast<std::size_t>(i) +
          static_cast<std::size_t>(dims[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims[1]) * k));
}

/// One record of an edit keyword: EQUALS/MULTIPLY/ADD/MINVALUE/MAXVALUE 'NAME' value box,
/// COPY 'FROM' 'TO' box.
struct PropertyEdit {
  std::string keyword;  ///< EQUALS, COPY, MULTIPLY, ADD, MINVALUE or MAXVALUE
  std::string name;     ///< the property changed (COPY: the source)
  std::string target;   ///< COPY: the property written
  double value = 0;
  CellBox box;
};

/// Applies `edit` to `properties` (one value per cell of `dims`). EQUALS and COPY
/// create the property they write (0 outside the box).
/// @return an empty string, or why the edit was not applied (a missing property).
std::string applyPropertyEdit(const PropertyEdit& edit, const std::array<int, 3>& dims,
                              std::map<std::string, std::vector<double>>& properties);

}  // namespace isovdb::reservoir
