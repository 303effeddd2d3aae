// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/dense_array.h"

#include <openvdb/tools/Dense.h>

#include "isovdb/errors.h"
#include "isovdb/volume/grids.h"

namespace isovdb::store {

namespace {

template <typename GridT, typename ValueT>
void copyBox(const GridT& grid, const volume::IndexBox& box, ValueT* out) {
  const openvdb::CoordBBox bbox(openvdb::Coord(box.min[0], box.min[1], box.min[2]),
                                openvdb::Coord(box.max[0], box.max[1], box.max[2]));
  openvdb::tools::Dense<ValueT, openvdb::tools::LayoutZYX> dense(bbox, out);
  openvdb::tools::copyToDense(grid, dense);
}

}  // namespace

volume::IndexBox defaultDenseBox(const volume::Volume& volume) {
  if (const auto sampled = volume::sampledBox(volume)) return *sampled;
  const volume::GridStats stats = volume.stats();
  return {.min = stats.bboxMin, .max = stats.bboxMax};
}

void copyToDense(const volume::Volume& volume, const volume::IndexBox& box, float* out) {
  if (volume.kind() == volume::VolumeKind::Mask)
    throw InputError("'" + volume.name() + "': a mask copies to a bool array, not a float one");
  copyBox(volume::fieldGrid(volume), box, out);
}

void copyToDense(const volume::Volume& volume, const volume::IndexBox& box, bool* out) {
  if (volume.kind() != volume::VolumeKind::Mask)
    throw InputError("'" + volume.name() + "': a " + std::string(volume::volumeKindName(volume.kind())) +
                     " volume copies to a float array, not a bool one");
  copyBox(volume::maskGrid(volume), box, out);
}

}  // namespace isovdb::store
