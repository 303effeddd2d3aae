// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/seam_cell.h"

namespace isovdb::contour {

void rebaseSeam(MetaCellSeam& seam, std::uint32_t base) noexcept {
  const auto rebase = [base](auto& ids) {
    for (std::uint32_t& v : ids)
      if (v != kNoVertex) v += base;
  };
  for (SeamCell& cell : seam.cells) {
    rebase(cell.vertices);
    rebase(cell.splitVertices);
  }
  for (SeamFace& face : seam.faces) face.vertex += base;
}

}  // namespace isovdb::contour
