// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/seam_cell.h"

namespace isovdb::contour {

SeamCell seamCellOf(const octree::OctreeLeaf& leaf, const std::array<int, 3>& metaCellOrigin, bool alternative) {
  SeamCell cell;
  cell.key = leaf.key;
  for (int a = 0; a < 3; ++a) cell.origin[a] = metaCellOrigin[a] + leaf.origin[a];
  cell.size = leaf.size;
  cell.cornerSigns = leaf.cornerSigns;
  cell.alternative = alternative;
  return cell;
}

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
