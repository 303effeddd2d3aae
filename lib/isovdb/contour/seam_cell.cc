#include "isovdb/contour/seam_cell.h"

namespace isovdb::contour {

void rebaseSeam(MetaCellSeam& seam, std::uint32_t base) noexcept {
  for (SeamCell& cell : seam.cells)
    if (cell.firstVertex != kNoVertex) cell.firstVertex += base;
  for (SeamFace& face : seam.faces) face.vertex += base;
}

}  // namespace isovdb::contour
