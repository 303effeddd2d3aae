#include "isovdb/contour/seam_cell.h"

namespace isovdb::contour {

void rebaseSeam(MetaCellSeam& seam, std::uint32_t base) noexcept {
  for (SeamCell& cell : seam.cells)
  {
    for (std::uint32_t& v : cell.vertices)
      if (v != kNoVertex) v += base;
    for (std::uint32_t& v : cell.splitVertices)
      if (v != kNoVertex) v += base;
  }
  for (SeamFace& face : seam.faces) face.vertex += base;
}

}  // namespace isovdb::contour
