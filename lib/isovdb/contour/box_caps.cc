// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/box_caps.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "isovdb/contour/adaptive_edges.h"

namespace isovdb::contour {

Vec3d besideDataBox(Vec3d p, const octree::OctreeLeaf& leaf, const std::array<int, 3>& treeOrigin,
                    const cell::DataBox& box) {
  const int size = leaf.size;
  const double m = 2 * kInteriorMargin * size;
  // The float nearest face + side * m, on the cell's side of the face (the mesh stores floats).
  const auto beside = [m](int face, double side) {
    const auto f = static_cast<float>(face + side * m);
    return static_cast<double>(
        f != static_cast<float>(face) ? f : std::nextafter(static_cast<float>(face), static_cast<float>(face + side)));
  };
  for (std::size_t a = 0; a < 3; ++a) {
    const int lo = treeOrigin[a] + leaf.origin[a];
    if (lo + size == box[0][a]) p[a] = std::max(p[a], beside(box[0][a], -1.0));
    if (lo == box[1][a]) p[a] = std::min(p[a], beside(box[1][a], 1.0));
  }
  return p;
}

float edgePointBesideDataBox(float t, const std::array<int, 3>& start, int axis, int size, float margin,
                             const cell::DataBox& box) {
  const auto a = static_cast<std::size_t>(axis);
  if (start[a] == box[1][a]) return margin;                                    // leaves through the max face
  if (start[a] + size == box[0][a]) return static_cast<float>(size) - margin;  // through the min face
  return t;
}

}  // namespace isovdb::contour
