// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/volume/sampled_box.h"

#include "isovdb/volume/grids.h"

namespace isovdb::volume {

namespace {
constexpr const char* kMinKey = "isovdb_sampled_min";
constexpr const char* kMaxKey = "isovdb_sampled_max";

openvdb::Vec3i toVec(const std::array<int, 3>& v) { return openvdb::Vec3i(v[0], v[1], v[2]); }
}  // namespace

void setSampledBox(const Volume& volume, const IndexBox& box) {
  openvdb::GridBase& grid = *volume.grid();
  grid.insertMeta(kMinKey, openvdb::Vec3IMetadata(toVec(box.min)));
  grid.insertMeta(kMaxKey, openvdb::Vec3IMetadata(toVec(box.max)));
}

std::optional<IndexBox> sampledBox(const Volume& volume) {
  if (!volume.grid()) return std::nullopt;
  const auto min = volume.grid()->getMetadata<openvdb::Vec3IMetadata>(kMinKey);
  const auto max = volume.grid()->getMetadata<openvdb::Vec3IMetadata>(kMaxKey);
  if (!min || !max) return std::nullopt;
  IndexBox box;
  for (int a = 0; a < 3; ++a) {
    box.min[a] = min->value()[a];
    box.max[a] = max->value()[a];
  }
  return box;
}

}  // namespace isovdb::volume
