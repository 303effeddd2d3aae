// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/vdb_grid_setup.h"

#include <mutex>

namespace isovdb::store {

void initializeOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

float levelSetWorldScale(const volume::Geometry& geometry) {
  return geometry.isUniform() ? static_cast<float>(geometry.spacing[0]) : 1.f;
}

void describeGrid(openvdb::GridBase& grid, const volume::Geometry& geometry, const std::string& name, bool levelSet,
                  const std::string& source) {
  openvdb::Mat4d m = openvdb::Mat4d::identity();
  for (int a = 0; a < 3; ++a) {
    m(a, a) = geometry.spacing[a];
    m(3, a) = geometry.origin[a];
  }
  grid.setTransform(openvdb::math::Transform::createLinearTransform(m));
  grid.setName(name);
  if (levelSet) {
    grid.setGridClass(openvdb::GRID_LEVEL_SET);
    if (!geometry.isUniform()) grid.insertMeta("isovdb_distance_units", openvdb::StringMetadata("voxels"));
  }
  grid.insertMeta("isovdb_source", openvdb::StringMetadata(source));
}

}  // namespace isovdb::store
