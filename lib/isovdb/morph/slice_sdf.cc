#include "isovdb/morph/slice_sdf.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/FastSweeping.h>

namespace isovdb::morph {

Field2 signedDistance(const Mask2& mask) {
  const std::int64_t area = mask.area();
  const float far = static_cast<float>(mask.width + mask.height);
  if (area == 0) return Field2::filled(mask.width, mask.height, far);
  if (area == static_cast<std::int64_t>(mask.inside.size())) return Field2::filled(mask.width, mask.height, -far);
  openvdb::initialize();
  // One layer of voxels: the background stands for the planes above and below. With
  // background "outside" the outside distances are in-plane (no interface across z),
  // with background "inside" the inside ones; each pass gives one sign.
  Field2 out = Field2::filled(mask.width, mask.height, far);
  for (const bool insidePass : {false, true}) {
    openvdb::FloatGrid fog(insidePass ? 1.f : 0.f);
    auto acc = fog.getAccessor();
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x) acc.setValueOn(openvdb::Coord(x, y, 0), mask.at(x, y) ? 1.f : 0.f);
    const openvdb::FloatGrid::Ptr sdf = openvdb::tools::fogToSdf(fog, 0.5f);
    const auto sdfAcc = sdf->getConstAccessor();
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x)
        if (mask.at(x, y) == insidePass) out.at(x, y) = sdfAcc.getValue(openvdb::Coord(x, y, 0));
  }
  return out;
}

}  // namespace isovdb::morph
