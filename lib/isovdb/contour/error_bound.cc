// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/error_bound.h"

#include <algorithm>

#include "isovdb/cell/trilinear.h"

namespace isovdb::contour {

std::vector<octree::MortonKey> leavesBeyondErrorBound(const cell::MetaCellSamples& samples,
                                                      const octree::LinearOctree& tree, const mesh::Mesh& mesh,
                                                      float iso, float maxError, int finestSize) {
  std::vector<octree::MortonKey> keys;
  const auto check = [&](Vec3f p) {
    for (int a = 0; a < 3; ++a) p[a] -= static_cast<float>(samples.origin[a]);
    if (cell::distanceToLevel(samples, p, iso) <= maxError) return;
    // Every leaf whose closed box holds p: a point on a face, an edge or a corner lies in several.
    constexpr float kNudge = 1e-3f;
    for (int corner = 0; corner < 8; ++corner) {
      Vec3f q = p;
      for (int a = 0; a < 3; ++a) q[a] += ((corner >> a) & 1) ? kNudge : -kNudge;
      const std::int64_t leaf = tree.findLeafContaining(q);
      if (leaf != octree::LinearOctree::kNone && tree.leaf(static_cast<std::size_t>(leaf)).size > finestSize)
        keys.push_back(tree.leaf(static_cast<std::size_t>(leaf)).key);
    }
  };
  for (const Vec3f& p : mesh.positions) check(p);
  for (const mesh::Triangle& t : mesh.triangles) {
    const Vec3f& a = mesh.positions[t[0]];
    const Vec3f& b = mesh.positions[t[1]];
    const Vec3f& c = mesh.positions[t[2]];
    check({(a[0] + b[0] + c[0]) / 3.0f, (a[1] + b[1] + c[1]) / 3.0f, (a[2] + b[2] + c[2]) / 3.0f});
    check({0.5f * (a[0] + b[0]), 0.5f * (a[1] + b[1]), 0.5f * (a[2] + b[2])});  // each edge from both sides:
    check({0.5f * (b[0] + c[0]), 0.5f * (b[1] + c[1]), 0.5f * (b[2] + c[2])});  // cheaper than a set of edges
    check({0.5f * (c[0] + a[0]), 0.5f * (c[1] + a[1]), 0.5f * (c[2] + a[2])});
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

}  // namespace isovdb::contour
