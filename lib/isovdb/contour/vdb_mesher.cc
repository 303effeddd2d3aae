// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/vdb_mesher.h"

#include <openvdb/tools/VolumeToMesh.h>

#include "isovdb/volume/grids.h"

namespace isovdb::contour {

namespace {

float squaredDistance(const openvdb::Vec3s& a, const openvdb::Vec3s& b) { return (a - b).lengthSqr(); }

}  // namespace

mesh::Mesh contourWithOpenVdb(const volume::Volume& field, const VdbMesherOptions& options, Interrupter* interrupter) {
  const volume::FieldGrid& grid = volume::fieldGrid(field);
  if (!(options.adaptivity >= 0.0 && options.adaptivity <= 1.0))
    throw InputError("adaptivity " + std::to_string(options.adaptivity) + " is out of range, expected 0..1");
  ProgressStage progress(interrupter, "contour (openvdb)");
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, options.iso, options.adaptivity);
  progress.update(1, 1);

  mesh::Mesh mesh;
  mesh.positions.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) mesh.positions[i] = {points[i][0], points[i][1], points[i][2]};
  mesh.triangles.reserve(triangles.size() + 2 * quads.size());
  // volumeToMesh winds its faces clockwise seen from the side of lower values (Houdini's
  // front faces), unless the grid's class is not a level set: then it inverts them
  // (VolumeToMesh.h, `invertSurfaceOrientation`). We write counter-clockwise faces seen
  // from outside: outside is above the isovalue on a distance field, below it on a scalar.
  const bool levelSetClass = grid.getGridClass() == openvdb::GRID_LEVEL_SET;
  const bool flip = (field.kind() == volume::VolumeKind::Scalar) != levelSetClass;
  auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    if (flip)
      mesh.triangles.push_back({a, c, b});
    else
      mesh.triangles.push_back({a, b, c});
  };
  for (const openvdb::Vec3I& t : triangles) emit(t[0], t[1], t[2]);
  for (const openvdb::Vec4I& q : quads) {
    if (squaredDistance(points[q[0]], points[q[2]]) <= squaredDistance(points[q[1]], points[q[3]])) {
      emit(q[0], q[1], q[2]);
      emit(q[0], q[2], q[3]);
    } else {
      emit(q[0], q[1], q[3]);
      emit(q[1], q[2], q[3]);
    }
  }
  return mesh;
}

}  // namespace isovdb::contour
