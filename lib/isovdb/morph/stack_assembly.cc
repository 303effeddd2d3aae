// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/morph/stack_assembly.h"

#include <openvdb/tools/FastSweeping.h>
#include <openvdb/tools/Morphology.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <algorithm>
#include <cmath>

#include "isovdb/volume/grids.h"

namespace isovdb::morph {

volume::Volume assembleStack(const std::vector<Field2>& planes, float halfWidth, const volume::Geometry& geometry,
                             const std::string& name) {
  openvdb::initialize();
  const float band = halfWidth + 1.f;
  auto grid = openvdb::FloatGrid::create(band);
  grid->setGridClass(openvdb::GRID_LEVEL_SET);
  const int depth = static_cast<int>(planes.size());
  if (depth > 0) {
    const int w = planes.front().width, h = planes.front().height;
    // Plane z in [-1, depth]: the two ends are empty (outside).
    auto value = [&](int x, int y, int z) -> float {
      if (z < 0 || z >= depth || x < 0 || y < 0 || x >= w || y >= h) return band;
      return std::clamp(planes[z].at(x, y), -band, band);
    };
    auto acc = grid->getAccessor();
    for (int z = -1; z <= depth; ++z)
      for (int y = -1; y <= h; ++y)
        for (int x = -1; x <= w; ++x) {
          const float v = value(x, y, z);
          bool keep = std::abs(v) < band;
          // A sign change to a neighbour must be seen even where both are far from
          // the in-plane boundary (a slice ending above a wide inside region).
          for (int d = 0; d < 6 && !keep; ++d) {
            const int dx = d == 0   ? -1
                           : d == 1 ? 1
                                    : 0,
                      dy = d == 2   ? -1
                           : d == 3 ? 1
                                    : 0,
                      dz = d == 4   ? -1
                           : d == 5 ? 1
                                    : 0;
            keep = (value(x + dx, y + dy, z + dz) <= 0) != (v <= 0);
          }
          if (keep) acc.setValueOn(openvdb::Coord(x, y, z), v);
        }
    openvdb::tools::signedFloodFill(grid->tree());
  }
  openvdb::FloatGrid::Ptr sdf;
  if (grid->activeVoxelCount() > 0) {
    // Widen the band to halfWidth in 3-D, then solve |∇φ| = 1 from the zero crossings
    // (fast sweeping keeps every voxel's sign, so each plane's inside is kept exactly).
    openvdb::tools::dilateActiveValues(grid->tree(), static_cast<int>(std::ceil(halfWidth)),
                                       openvdb::tools::NN_FACE_EDGE_VERTEX, openvdb::tools::IGNORE_TILES);
    sdf = openvdb::tools::sdfToSdf(*grid, 0.f);
  } else {
    sdf = openvdb::FloatGrid::create(band);
  }
  sdf->setGridClass(openvdb::GRID_LEVEL_SET);
  sdf->setName(name);
  return volume::Volume(volume::VolumeKind::DistanceField, sdf, geometry, name);
}

}  // namespace isovdb::morph
