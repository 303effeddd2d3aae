// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/octree_contour.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_pipeline.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iterator>
#include <cmath>
#include <memory>

#include "isovdb/contour/adaptive_contour.h"
#include "isovdb/contour/error_bound.h"
#include "isovdb/contour/regular_contour.h"
#include "isovdb/errors.h"
#include "isovdb/octree/surface_cells.h"
#include "isovdb/stitch/stitch_seams.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/meta_cells.h"

namespace isovdb::pipeline {

namespace {

constexpr int kMargin = 2;  // single block: voxels between the band and the meta-cell boundary

int nextPowerOfTwo(int v) {
  int p = 1;
  while (p < v) p *= 2;
  return p;
}

/// What the engine reads for every meta-cell: the shared settings, the octree's own
/// knobs and the partition's size.
struct Engine {
  const cell::ContourSettings& settings;
  const octree::OctreeOptions& tree;
  int metaCellSize;
};

/// Figures summed over meta-cells (CPU seconds, counts).
struct MetaCellTotals {
  double readSeconds = 0, octreeSeconds = 0, contourSeconds = 0;
  std::int64_t leaves = 0;
  std::int64_t errorBoundPasses = 0;       // blocks built again because their mesh broke the error bound
  std::int64_t errorBoundLeavesSplit = 0;  // leaves those passes split
  octree::OctreeBuildStats build;
  contour::RegularContourStats regular;
  contour::AdaptiveContourStats adaptive;

  void add(const MetaCellTotals& o) {
    readSeconds += o.readSeconds;
    octreeSeconds += o.octreeSeconds;
    contourSeconds += o.contourSeconds;
    leaves += o.leaves;
    errorBoundPasses += o.errorBoundPasses;
    errorBoundLeavesSplit += o.errorBoundLeavesSplit;
    build += o.build;
    regular += o.regular;
    adaptive += o.adaptive;
  }
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Builds the octree of one block of samples and contours it (edges inside the block; the seam kept).
/// `iso` is the settings' isovalue as the engine reads this block (negated on a scalar field).
/// `finalTree` (optional) receives the tree the mesh was contoured from.
contour::MetaCellMesh contourBlock(const cell::MetaCellSamples& samples, const Engine& engine, float iso,
                                   MetaCellTotals& totals, Interrupter* interrupter,
                                   octree::LinearOctree* finalTree = nullptr) {
  cell::ContourSettings settings = engine.settings;
  settings.iso = iso;
  octree::OctreeOptions options = engine.tree;
  const bool bounded = settings.method == cell::ContourMethod::Adaptive && options.maxError > 0.0f;
  for (;;) {
    auto t0 = std::chrono::steady_clock::now();
    octree::OctreeBuildStats buildStats;
    const octree::LinearOctree tree = octree::buildContourTree(samples, settings, options, &buildStats, interrupter);
    totals.octreeSeconds += secondsSince(t0);
    t0 = std::chrono::steady_clock::now();
    contour::MetaCellMesh result;
    contour::RegularContourStats regularStats;
    contour::AdaptiveContourStats adaptiveStats;
    if (settings.method == cell::ContourMethod::Regular)
      result = contour::contourRegularMetaCell(samples, tree, settings, &regularStats);
    else
      result = contour::contourAdaptiveMetaCell(samples, tree, settings, &adaptiveStats);
    // The error bound's second look: leaves whose mesh strays beyond it are split and
    // the block built again (each pass only deepens the tree, so this ends).
    std::vector<octree::MortonKey> beyond;
    if (bounded) {
      const int finest = octree::cellSizeAtDepth(samples.size, octree::resolveDepths(options, samples.size).maxDepth);
      beyond = contour::leavesBeyondErrorBound(samples, tree, result.mesh, settings.iso, options.maxError, finest);
    }
    totals.contourSeconds += secondsSince(t0);
    std::vector<octree::MortonKey> forced;
    std::set_union(options.forcedSplits.begin(), options.forcedSplits.end(), beyond.begin(), beyond.end(),
                   std::back_inserter(forced));
    // A pass that would split nothing new (none should: beyond holds leaves only) ends the loop.
    if (forced.size() > options.forcedSplits.size()) {
      ++totals.errorBoundPasses;
      totals.errorBoundLeavesSplit += static_cast<std::int64_t>(forced.size() - options.forcedSplits.size());
      options.forcedSplits = std::move(forced);
      continue;
    }
    totals.leaves += static_cast<std::int64_t>(tree.leafCount());
    totals.build += buildStats;
    totals.regular += regularStats;
    totals.adaptive += adaptiveStats;
    if (finalTree) *finalTree = tree;
    return result;
  }
}

/// The engine's inside is value <= iso; a scalar's inside is above the isovalue.
float engineIso(const volume::Volume& field, float iso, cell::MetaCellSamples& samples) {
  if (field.kind() != volume::VolumeKind::Scalar) return iso;
  for (float& v : samples.values) v = -v;
  return -iso;
}

void recordTotals(const MetaCellTotals& totals, const cell::ContourSettings& options, Statistics::Json& section) {
  const bool regular = options.method == cell::ContourMethod::Regular;
  const contour::RegularContourStats& r = totals.regular;
  const contour::AdaptiveContourStats& a = totals.adaptive;
  section["leaves"] = totals.leaves;
  section["complex_cells"] = totals.build.complexCells;
  section["unresolved_complex_leaves"] = totals.build.unresolvedComplexLeaves;
  section["boundary_cells_kept"] = regular ? r.seamCells : a.seamCells;
  section["edges_left_to_stitching"] = regular ? r.boundaryEdges : a.boundaryEdges;
  section["manifold_fixes"] = regular ? r.manifoldFixes : a.manifoldFixes;
  if (regular) {
    section["topology"] = std::string(cell::regularTopologyName(options.topology));
    section["manifold_fixes_beyond_apron"] = r.fixesBeyondApron;
    if (options.topology == cell::RegularTopology::Voxels) section["tube_cells"] = r.tubeCells;
  } else {
    section["geometric_splits"] = totals.build.geometricSplits;
    section["error_bound_splits"] = totals.build.errorBoundSplits;
    section["error_bound_passes"] = totals.errorBoundPasses;
    section["error_bound_leaves_split"] = totals.errorBoundLeavesSplit;
    section["multi_sheet_splits"] = totals.build.multiSheetSplits;
    section["data_box_splits"] = totals.build.dataBoxSplits;
    section["hidden_component_splits"] = totals.build.hiddenComponentSplits;
    section["multi_vertex_cells"] = a.multiVertexCells;
    section["intersection_free"] = options.intersectionFree;
    section["sharp_features"] = options.sharpFeatures;
    section["minimal_edges"] = a.minimalEdges;
    section["fanned_edges"] = a.fannedEdges;
    section["triangles_added_by_fans"] = a.trianglesAddedByFans;
  }
  section["cpu_seconds_read"] = totals.readSeconds;
  section["cpu_seconds_octree"] = totals.octreeSeconds;
  section["cpu_seconds_contour"] = totals.contourSeconds;
}

/// One padded meta-cell around the whole band (no seams).
void contourSingleBlock(const volume::Volume& field, const Engine& engine, mesh::MeshSink& sink,
                        Interrupter* interrupter, Statistics* stats) {
  openvdb::CoordBBox band;
  if (!volume::fieldGrid(field).tree().evalActiveVoxelBoundingBox(band)) return;
  std::array<int, 3> origin;
  int extent = 1;
  for (int a = 0; a < 3; ++a) {
    origin[a] = band.min()[a] - kMargin;
    extent = std::max(extent, band.max()[a] + kMargin - origin[a]);
  }
  const int size = nextPowerOfTwo(extent);
  // The block is dense: refuse clearly rather than let the kernel kill the process half-way.
  const double blockBytes = std::pow(static_cast<double>(size) + 3.0, 3.0) * sizeof(float);
  const double physicalBytes = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * ::sysconf(_SC_PAGE_SIZE);
  if (physicalBytes > 0 && blockBytes > 0.5 * physicalBytes)
    throw InputError("'" + field.name() + "': the surface spans " + std::to_string(extent) +
                     " voxels; one meta-cell of " + std::to_string(size) + "^3 samples needs " +
                     std::to_string(static_cast<long long>(blockBytes / (1 << 20))) +
                     " MiB, more than half of this machine's memory (use --meta-cell 128)");
  MetaCellTotals totals;
  cell::MetaCellSamples samples;
  float iso = engine.settings.iso;
  {
    Statistics::StageTimer timer(stats, "read_meta_cells");
    volume::readBlock(field, origin, size, samples);
    iso = engineIso(field, iso, samples);
  }
  contour::MetaCellMesh block;
  {
    Statistics::StageTimer timer(stats, "contour_meta_cells");
    block = contourBlock(samples, engine, iso, totals, interrupter);
  }
  sink.addVertices(block.mesh.positions);
  sink.addTriangles(block.mesh.triangles);
  if (stats) {
    Statistics::Json section = Statistics::Json::object();
    section["meta_cell_size"] = size;
    section["meta_cell_origin"] = origin;
    section["single_block"] = true;
    recordTotals(totals, engine.settings, section);
    (*stats)["octree"] = section;
  }
}

/// The samples read beyond a meta-cell: regular mode reads one finest cell beyond it,
/// for Wenger's fix across the seam; adaptive mode one sample (Prewitt gradients).
int metaCellApron(const Engine& engine) {
  if (engine.settings.method != cell::ContourMethod::Regular) return 1;
  const octree::OctreeDepths depths = octree::resolveDepths(engine.tree, engine.metaCellSize);
  return std::max(1, octree::cellSizeAtDepth(engine.metaCellSize, depths.maxDepth));
}

/// One meta-cell's result on its way through the pipeline.
struct MetaCellJob {
  std::size_t position = 0;
  bool contoured = false;  ///< its samples change sign
  contour::MetaCellMesh result;
  MetaCellTotals totals;
};

/// Every meta-cell in parallel, output in meta-cell order, then the seams.
void contourMetaCells(const volume::Volume& field, const Engine& engine, mesh::MeshSink& sink, Interrupter* interrupter,
                      Statistics* stats) {
  const cell::ContourSettings& options = engine.settings;
  const int s = engine.metaCellSize;
  if (s < 16 || s > 512 || (s & (s - 1)) != 0)
    throw InputError("--meta-cell: expected a power of two in 16..512 (or 0 for one block), got " + std::to_string(s));
  volume::MetaCellPartition partition;
  {
    Statistics::StageTimer timer(stats, "partition");
    partition = volume::partitionMetaCells(field, s, options.iso);
  }
  // Regular mode reads one finest cell beyond the meta-cell, for Wenger's fix across the seam.
  const int apron = metaCellApron(engine);

  const std::size_t tokens =
      std::max<std::size_t>(1, tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  stitch::SeamStore seams;
  MetaCellTotals totals;
  std::size_t next = 0, contoured = 0, done = 0;
  const std::size_t total = partition.cells.size();
  // One sample block per thread, reused meta-cell after meta-cell: a fresh 9 MB
  // block per meta-cell had every page faulted in again.
  tbb::enumerable_thread_specific<cell::MetaCellSamples> sampleBlocks;
  {
    Statistics::StageTimer timer(stats, "contour_meta_cells");
    ProgressStage progress(interrupter, "contouring meta-cells");
    tbb::parallel_pipeline(tokens, tbb::make_filter<void, std::shared_ptr<MetaCellJob>>(
                                       tbb::filter_mode::serial_in_order,
                                       [&](tbb::flow_control& control) -> std::shared_ptr<MetaCellJob> {
                                         if (next >= total) {
                                           control.stop();
                                           return nullptr;
                                         }
                                         auto job = std::make_shared<MetaCellJob>();
                                         job->position = next++;
                                         return job;
                                       }) &
                                       tbb::make_filter<std::shared_ptr<MetaCellJob>, std::shared_ptr<MetaCellJob>>(
                                           tbb::filter_mode::parallel,
                                           [&](std::shared_ptr<MetaCellJob> job) {
                                             const auto t0 = std::chrono::steady_clock::now();
                                             cell::MetaCellSamples& samples = sampleBlocks.local();
                                             volume::readMetaCell(field, partition.cells[job->position], s, samples,
                                                                  apron);
                                             const float iso = engineIso(field, options.iso, samples);
                                             job->totals.readSeconds += secondsSince(t0);
                                             job->contoured = volume::hasSignChange(samples, iso);
                                             if (job->contoured)
                                               job->result = contourBlock(samples, engine, iso, job->totals, nullptr);
                                             return job;
                                           }) &
                                       tbb::make_filter<std::shared_ptr<MetaCellJob>, void>(
                                           tbb::filter_mode::serial_in_order, [&](std::shared_ptr<MetaCellJob> job) {
                                             totals.add(job->totals);
                                             if (job->contoured) {
                                               ++contoured;
                                               const auto base = static_cast<std::uint32_t>(sink.vertexCount());
                                               for (mesh::Triangle& t : job->result.mesh.triangles)
                                                 for (std::uint32_t& v : t) v += base;
                                               sink.addVertices(job->result.mesh.positions);
                                               sink.addTriangles(job->result.mesh.triangles);
                                               contour::rebaseSeam(job->result.seam, base);
                                               seams.add(partition.cells[job->position], std::move(job->result.seam));
                                             }
                                             progress.update(static_cast<double>(++done), static_cast<double>(total));
                                           }));
  }

  stitch::StitchStats stitchStats;
  {
    Statistics::StageTimer timer(stats, "stitch");
    mesh::Mesh tail;
    stitch::stitchSeams(seams, options, s, static_cast<std::uint32_t>(sink.vertexCount()), tail, &stitchStats,
                        interrupter);
    sink.addVertices(tail.positions);
    sink.addTriangles(tail.triangles);
  }
  if (stats) {
    Statistics::Json section = Statistics::Json::object();
    section["meta_cell_size"] = s;
    section["apron"] = apron;
    section["threads"] = tokens;
    section["candidates"] = total;
    section["contoured"] = contoured;
    section["skipped_without_sign_change"] = total - contoured;
    section["leaves_scanned_for_partition"] = partition.leavesScanned;
    recordTotals(totals, options, section);
    (*stats)["meta_cells"] = section;
    Statistics::Json st = Statistics::Json::object();
    st["meta_faces"] = stitchStats.metaFaces;
    st["meta_edges"] = stitchStats.metaEdges;
    st["seam_cells"] = stitchStats.seamCells;
    st["edges"] = stitchStats.edges;
    if (options.method == cell::ContourMethod::Adaptive) st["fanned_edges"] = stitchStats.fannedEdges;
    st["missing_cells"] = stitchStats.missingCells;
    (*stats)["stitch"] = st;
  }
}

}  // namespace

void contourWithOctree(const volume::Volume& field, const cell::ContourSettings& settings,
                       const octree::OctreeOptions& tree, int metaCellSize, mesh::MeshSink& sink,
                       Interrupter* interrupter, Statistics* stats) {
  if (field.kind() == volume::VolumeKind::Mask)
    throw InputError("'" + field.name() + "': octree contouring needs a distance field or a scalar field");
  if (settings.method == cell::ContourMethod::Vdb)
    throw InputError("octree contouring: the method is vdb; expected regular or adaptive");
  const Engine engine{settings, tree, metaCellSize};
  if (metaCellSize == 0)
    contourSingleBlock(field, engine, sink, interrupter, stats);
  else
    contourMetaCells(field, engine, sink, interrupter, stats);
}

octree::LinearOctree metaCellOctree(const volume::Volume& field, const cell::ContourSettings& settings,
                                    const octree::OctreeOptions& tree, int metaCellSize,
                                    const std::array<int, 3>& index, octree::OctreeBuildStats* stats,
                                    bool* hasSignChange, Interrupter* interrupter) {
  const Engine engine{settings, tree, metaCellSize};
  cell::MetaCellSamples samples;
  volume::readMetaCell(field, index, metaCellSize, samples, metaCellApron(engine));
  cell::ContourSettings blockSettings = settings;
  blockSettings.iso = engineIso(field, settings.iso, samples);
  if (hasSignChange) *hasSignChange = volume::hasSignChange(samples, blockSettings.iso);
  if (settings.method != cell::ContourMethod::Adaptive || tree.maxError <= 0.0f)
    return octree::buildContourTree(samples, blockSettings, tree, stats, interrupter);
  // Under an error bound the tree extract keeps is the one its mesh holds the bound on.
  MetaCellTotals totals;
  octree::LinearOctree result;
  contourBlock(samples, engine, blockSettings.iso, totals, interrupter, &result);
  if (stats) *stats = totals.build;
  return result;
}

mesh::Mesh contourWithOctree(const volume::Volume& field, const cell::ContourSettings& settings,
                             const octree::OctreeOptions& tree, int metaCellSize, Interrupter* interrupter,
                             Statistics* stats) {
  mesh::MeshCollector collector;
  contourWithOctree(field, settings, tree, metaCellSize, collector, interrupter, stats);
  return std::move(collector.mesh);
}

}  // namespace isovdb::pipeline
