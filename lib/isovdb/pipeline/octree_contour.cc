#include "isovdb/pipeline/octree_contour.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "isovdb/contour/adaptive_contour.h"
#include "isovdb/contour/regular_contour.h"
#include "isovdb/errors.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/meta_cells.h"

namespace isovdb::pipeline {

namespace {

constexpr int kMargin = 2;  // voxels between the band and the meta-cell boundary

int nextPowerOfTwo(int v) {
  int p = 1;
  while (p < v) p *= 2;
  return p;
}

}  // namespace

mesh::Mesh contourWithOctree(const volume::Volume& field, const OctreeContourOptions& options,
                             Interrupter* interrupter, Statistics* stats) {
  if (field.kind() == volume::VolumeKind::Mask)
    throw InputError("'" + field.name() + "': octree contouring needs a distance field or a scalar field");
  // One meta-cell around the whole active band (no stitching yet). Only the
  // bounding box is needed, not Volume::stats()'s value range and memory walk.
  openvdb::CoordBBox band;
  if (!volume::fieldGrid(field).tree().evalActiveVoxelBoundingBox(band)) return {};
  std::array<int, 3> origin;
  int extent = 1;
  for (int a = 0; a < 3; ++a) {
    origin[a] = band.min()[a] - kMargin;
    extent = std::max(extent, band.max()[a] + kMargin - origin[a]);
  }
  const int size = nextPowerOfTwo(extent);
  // Until stitching lands the block is dense: refuse clearly rather than let the
  // kernel kill the process half-way.
  const double blockBytes = std::pow(static_cast<double>(size) + 3.0, 3.0) * sizeof(float);
  const double physicalBytes = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * ::sysconf(_SC_PAGE_SIZE);
  if (physicalBytes > 0 && blockBytes > 0.5 * physicalBytes)
    throw InputError("'" + field.name() + "': the surface spans " + std::to_string(extent) +
                     " voxels; one meta-cell of " + std::to_string(size) + "^3 samples needs " +
                     std::to_string(static_cast<long long>(blockBytes / (1 << 20))) +
                     " MiB, more than half of this machine's memory (use --method vdb until seam stitching lands)");
  octree::MetaCellSamples samples;
  float iso = options.iso;
  {
    Statistics::StageTimer timer(stats, "read_meta_cells");
    volume::readBlock(field, origin, size, samples);
    // The engine's inside is value <= iso; a scalar's inside is above the isovalue.
    if (field.kind() == volume::VolumeKind::Scalar) {
      for (float& v : samples.values) v = -v;
      iso = -iso;
    }
  }

  octree::OctreeOptions treeOptions;
  treeOptions.construction = options.method == OctreeMethod::Regular ? octree::OctreeConstruction::Regular
                                                                     : octree::OctreeConstruction::Adaptive;
  treeOptions.minDepth = options.minLevel;
  if (options.minLevel < 0) treeOptions.maxCellSize = std::min(options.maxCellSize, size);
  treeOptions.maxDepth = options.maxLevel;
  if (options.maxLevel < 0) treeOptions.finestCellSize = options.finestCellSize;
  treeOptions.qefTolerance = options.method == OctreeMethod::Adaptive ? options.qefTolerance : -1.f;
  treeOptions.iso = iso;
  octree::OctreeBuildStats buildStats;
  octree::LinearOctree tree;
  {
    Statistics::StageTimer timer(stats, "octree");
    tree = octree::buildOctree(samples, treeOptions, &buildStats, interrupter);
  }

  mesh::Mesh mesh;
  Statistics::Json section = Statistics::Json::object();
  section["meta_cell_size"] = size;
  section["meta_cell_origin"] = origin;
  section["leaves"] = tree.leafCount();
  section["complex_cells"] = buildStats.complexCells;
  section["unresolved_complex_leaves"] = buildStats.unresolvedComplexLeaves;
  section["geometric_splits"] = buildStats.geometricSplits;
  {
    Statistics::StageTimer timer(stats, "contour");
    if (options.method == OctreeMethod::Regular) {
      contour::RegularContourStats contourStats;
      mesh = contour::contourRegular(samples, tree, {.iso = iso, .manifoldFix = options.manifoldFix}, &contourStats);
      section["manifold_fixes"] = contourStats.manifoldFixes;
      section["quads"] = contourStats.quads;
    } else {
      contour::AdaptiveContourStats contourStats;
      mesh = contour::contourAdaptive(samples, tree, {.iso = iso, .intersectionFree = options.intersectionFree},
                                      &contourStats);
      section["intersection_free"] = options.intersectionFree;
      section["minimal_edges"] = contourStats.minimalEdges;
      section["fanned_edges"] = contourStats.fannedEdges;
      section["triangles_added_by_fans"] = contourStats.trianglesAddedByFans;
    }
  }
  if (stats) (*stats)["octree"] = section;
  return mesh;
}

}  // namespace isovdb::pipeline
