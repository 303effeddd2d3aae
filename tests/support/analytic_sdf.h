// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file analytic_sdf.h
/// @brief Exact signed distance fields of simple solids (negative inside, global
///        index coordinates) and their OpenVDB level sets, for tests that need a
///        field with known sharp features.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "isovdb/volume/grids.h"

namespace isovdb::test {

/// Capped cylinder along z: centre `c`, radius `r`, half height `halfHeight`.
inline double cylinderSdf(const std::array<double, 3>& p, const std::array<double, 3>& c, double r, double halfHeight) {
  const double qr = std::hypot(p[0] - c[0], p[1] - c[1]) - r, qz = std::abs(p[2] - c[2]) - halfHeight;
  return std::min(std::max(qr, qz), 0.0) + std::hypot(std::max(qr, 0.0), std::max(qz, 0.0));
}

/// `sdf` over [-2, size + 2]^3 as an OpenVDB level set (narrow band 3 voxels, ±3 beyond).
template <class F>
volume::Volume levelSetVolume(int size, F&& sdf) {
  auto grid = openvdb::FloatGrid::create(3.0f);
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  auto accessor = grid->getAccessor();
  for (int z = -2; z <= size + 2; ++z)
    for (int y = -2; y <= size + 2; ++y)
      for (int x = -2; x <= size + 2; ++x) {
        const auto v = static_cast<float>(sdf(std::array<double, 3>{double(x), double(y), double(z)}));
        if (std::abs(v) < 3.0f)
          accessor.setValue(openvdb::Coord(x, y, z), v);
        else
          accessor.setValueOff(openvdb::Coord(x, y, z), v < 0 ? -3.0f : 3.0f);
      }
  return volume::Volume(volume::VolumeKind::DistanceField, grid, volume::Geometry{}, "analytic");
}

}  // namespace isovdb::test
