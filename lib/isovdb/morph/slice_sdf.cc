// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/slice_sdf.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/FastSweeping.h>

#include <algorithm>

namespace isovdb::morph {

namespace {

/// Pixels swept around the object's bounding box.
constexpr int kMargin = 16;

}  // namespace

Field2 signedDistance(const Mask2& mask) {
  const std::int64_t area = mask.area();
  const float far = static_cast<float>(mask.width + mask.height);
  if (area == 0) return Field2::filled(mask.width, mask.height, far);
  if (area == static_cast<std::int64_t>(mask.inside.size())) return Field2::filled(mask.width, mask.height, -far);
  openvdb::initialize();
  // Only a margin around the object is swept; farther pixels continue the crop's
  // border by their distance to it (Field2::sample), positive and growing.
  int x0 = mask.width, y0 = mask.height, x1 = -1, y1 = -1;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x)
      if (mask.at(x, y)) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
  x0 = std::max(0, x0 - kMargin);
  y0 = std::max(0, y0 - kMargin);
  x1 = std::min(mask.width - 1, x1 + kMargin);
  y1 = std::min(mask.height - 1, y1 + kMargin);
  Field2 crop = Field2::filled(x1 - x0 + 1, y1 - y0 + 1, far);
  // One layer of voxels: the background stands for the planes above and below. With
  // background "outside" the outside distances are in-plane (no interface across z),
  // with background "inside" the inside ones; each pass gives one sign.
  for (const bool insidePass : {false, true}) {
    openvdb::FloatGrid fog(insidePass ? 1.f : 0.f);
    auto acc = fog.getAccessor();
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) acc.setValueOn(openvdb::Coord(x, y, 0), mask.at(x, y) ? 1.f : 0.f);
    const openvdb::FloatGrid::Ptr sdf = openvdb::tools::fogToSdf(fog, 0.5f);
    const auto sdfAcc = sdf->getConstAccessor();
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        if (mask.at(x, y) == insidePass) crop.at(x - x0, y - y0) = sdfAcc.getValue(openvdb::Coord(x, y, 0));
  }
  Field2 out = Field2::filled(mask.width, mask.height, far);
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) out.at(x, y) = crop.sample(x - x0, y - y0);
  return out;
}

}  // namespace isovdb::morph
