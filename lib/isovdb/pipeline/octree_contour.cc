// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/octree_contour.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iterator>
#include <limits>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>

#include "isovdb/cell/gradient.h"
#include "isovdb/contour/adaptive_contour.h"
#include "isovdb/contour/error_bound.h"
#include "isovdb/contour/regular_contour.h"
#include "isovdb/octree/unit_edge_crossings.h"
#include "isovdb/errors.h"
#include "isovdb/pipeline/load_volume.h"
#include "isovdb/octree/surface_cells.h"
#include "isovdb/stitch/stitch_seams.h"
#include "isovdb/volume/grids.h"
#include "isovdb/volume/meta_cells.h"
#include "isovdb/volume/slab_band.h"

namespace isovdb::pipeline {

namespace {

constexpr int kMargin = 2;  // single block: voxels between the band and the meta-cell boundary
/// Meta-cells in flight per worker thread. With one, a thread whose block finished before
/// an earlier one waited for it (the output is in order) and only helped with that block's
/// parallel loops, not its serial parts: the 1024^3 salt's adaptive contouring kept two
/// cores 80 % busy. Each extra token holds one finished block's mesh until its turn.
constexpr std::size_t kTokensPerThread = 4;

int nextPowerOfTwo(int v) {
  int p = 1;
  while (p < v) p *= 2;
  return p;
}

/// What the engine reads for every meta-cell: the shared settings, the octree's own
/// knobs, the partition's size and the largest |value| a sample can hold (every block
/// derives the same far-outside value from it, so blocks agree on their seams).
struct Engine {
  const cell::ContourSettings& settings;
  const octree::OctreeOptions& tree;
  int metaCellSize;
  float valueBound = 0.0f;
};

/// The largest |value| a sample of `field` reads: its active values' and its background's.
float valueBound(const volume::Volume& field) {
  const volume::GridStats stats = field.stats();
  return std::max(
      {std::abs(stats.minValue), std::abs(stats.maxValue), std::abs(volume::fieldGrid(field).background())});
}

/// Figures summed over meta-cells (CPU seconds, counts).
struct MetaCellTotals {
  double readSeconds = 0, octreeSeconds = 0, contourSeconds = 0, errorBoundSeconds = 0;
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
    errorBoundSeconds += o.errorBoundSeconds;
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
/// `finalTree` (optional) receives the tree the mesh was contoured from. `givenPhases`: the
/// samples' phases at `iso` where the caller has them (else computed here).
contour::MetaCellMesh contourBlock(const cell::MetaCellSamples& samples, const Engine& engine, float iso,
                                   MetaCellTotals& totals, Interrupter* interrupter,
                                   octree::LinearOctree* finalTree = nullptr,
                                   const octree::SamplePhases* givenPhases = nullptr) {
  cell::ContourSettings settings = engine.settings;
  settings.iso = iso;
  octree::OctreeOptions options = engine.tree;
  const bool bounded = settings.method == cell::ContourMethod::Adaptive && options.maxError > 0.0f;
  const int finest = bounded ? octree::finestLeafSize(options, samples.size) : 1;
  // Every bipolar unit edge's crossing, found once for the whole block (each is shared by
  // four 1-voxel cells): regular mode's tree has only 1-voxel surface leaves, and the error
  // bound places a vertex in every unit cell of the coarse leaves, pass after pass. The
  // bound's tree reads them too (a coarse cell's crossings are those of unit edges), so there
  // the table comes first where its fixed part is small; else it is built after the first
  // tree, which tells whether the table pays for its memory. (Without the bound, building it
  // for the tree alone made adaptive mode 7 % slower on the 512^3 blobs.)
  const bool adaptive = settings.method == cell::ContourMethod::Adaptive;
  const bool wantsCrossings = settings.contoursByMinimalEdges() && (!adaptive || bounded);
  // The samples' phases, read by the tree, the crossings' table and the error bound (each
  // computed its own: a pass over the block's floats, 4 % of an adaptive run).
  auto t0 = std::chrono::steady_clock::now();
  std::optional<octree::SamplePhases> ownPhases;
  if (givenPhases == nullptr) ownPhases.emplace(samples, iso);
  const octree::SamplePhases& phases = givenPhases ? *givenPhases : *ownPhases;
  totals.octreeSeconds += secondsSince(t0);
  std::optional<octree::UnitEdgeCrossings> crossings;
  bool crossingsDecided = false;
  if (adaptive && wantsCrossings && octree::UnitEdgeCrossings::smallEnough(samples.size)) {
    t0 = std::chrono::steady_clock::now();
    crossings.emplace(samples, phases, iso, settings.sharpFeatures);
    crossingsDecided = true;
    totals.octreeSeconds += secondsSince(t0);
  }
  // The error bound's passes build the tree again with a few more forced splits: every other
  // cell coarser than a voxel is recalled from the builds before. Kept from the first build
  // on, since most blocks take one pass at most (kept from the second, it saved nothing):
  // 0.87-0.88x the wall time where passes pile up (256^3 gyroid, 512^3 salt at E = 0.5),
  // for 2-9 % more peak memory. Unit cells are evaluated again: they are most of a mask's
  // cells and the cheapest (no vertex to place), and keeping them cost 12-15 % more.
  std::optional<octree::BuildMemo> memo;
  if (bounded) memo.emplace();
  for (;;) {
    t0 = std::chrono::steady_clock::now();
    octree::OctreeBuildStats buildStats;
    const octree::LinearOctree tree =
        octree::buildContourTree(samples, settings, options, &buildStats, interrupter,
                                 crossings ? &*crossings : nullptr, &phases, memo ? &*memo : nullptr);
    totals.octreeSeconds += secondsSince(t0);
    t0 = std::chrono::steady_clock::now();
    if (wantsCrossings && !crossingsDecided) {
      crossingsDecided = true;
      const auto surfaceLeaves = static_cast<std::size_t>(std::count_if(
          tree.leaves().begin(), tree.leaves().end(), [](const octree::OctreeLeaf& l) { return l.surface; }));
      if (octree::UnitEdgeCrossings::pays(samples.size, surfaceLeaves))
        crossings.emplace(samples, phases, iso, settings.sharpFeatures);
    }
    const octree::UnitEdgeCrossings* unitCrossings = crossings ? &*crossings : nullptr;
    contour::MetaCellMesh result;
    contour::RegularContourStats regularStats;
    contour::AdaptiveContourStats adaptiveStats;
    if (settings.contoursByMinimalEdges())
      result = contour::contourAdaptiveMetaCell(samples, tree, settings, &adaptiveStats, unitCrossings);
    else
      result = contour::contourRegularMetaCell(samples, tree, settings, &regularStats, &phases);
    totals.contourSeconds += secondsSince(t0);
    t0 = std::chrono::steady_clock::now();
    // The error bound's second look: leaves whose mesh strays beyond it are split and
    // the block built again (each pass only deepens the tree, so this ends).
    std::vector<octree::MortonKey> beyond;
    if (bounded)
      beyond = contour::leavesBeyondErrorBound(samples, tree, result.mesh, cell::dualVertexOptions(settings),
                                               options.maxError, finest, unitCrossings, &phases, &result.seam);
    if (bounded && !result.apartFromRegular.empty()) {
      // Quads that could not take regular mode's triangulation: measured against regular mode's
      // quad while contouring, held to the bound less the check's margin as its samples are.
      for (const contour::MetaCellMesh::LeafApart& a : result.apartFromRegular) {
        const octree::OctreeLeaf& leaf = tree.leaf(static_cast<std::size_t>(a.leaf));
        if (leaf.size > finest && a.distance > options.maxError - octree::kErrorBoundMargin) beyond.push_back(leaf.key);
      }
      std::sort(beyond.begin(), beyond.end());
      beyond.erase(std::unique(beyond.begin(), beyond.end()), beyond.end());
    }
    totals.errorBoundSeconds += secondsSince(t0);
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

/// Samples beyond the data's box read as far outside: the engine's iso plus 10^4 times the
/// deepest inside value any sample can have (`bound` + |iso|). An edge from the last sample
/// inside to one beyond the box then crosses within 10^-4 voxel of the box face, so the
/// contouring itself makes the cap, flat on the face (contour/adaptive_contour.cc keeps its
/// vertices within 2 * 10^-3 voxel beyond it), and nothing moves a vertex afterwards.
/// Flattening a cap that lay up to a voxel beyond onto the face, after Ju–Udeshi's test had
/// passed the positions before, folded its triangles (F3 above 3000: 7 self-intersecting pairs).
void farOutsideBeyondDataBox(cell::MetaCellSamples& samples, float iso, float bound,
                             const std::optional<cell::DataBox>& box) {
  samples.boxRim.active = false;
  if (!box) return;
  const int lo = -samples.apron, hi = samples.size + samples.apron;
  bool beyond = false;
  for (int a = 0; a < 3; ++a)
    beyond = beyond || samples.origin[a] + lo < (*box)[0][a] || samples.origin[a] + hi > (*box)[1][a];
  if (!beyond) return;
  // The cells inside the box keep the field's own normals (cell/box_rim_gradients.h).
  cell::keepBoxRimGradients(samples, (*box)[0], (*box)[1]);
  // At most 1e18 (hostile or non-finite values): the gradients' squares stay finite
  // floats. Always above the iso, even where adding to a huge iso changes nothing.
  float reach = 1e4f * (bound + std::abs(iso) + 1.0f);
  if (!(reach < 1e18f)) reach = 1e18f;
  const float far = std::max(iso + reach, std::nextafter(iso, std::numeric_limits<float>::infinity()));
  // Sample offsets [first, last] along axis a that lie inside the box.
  const auto insideRange = [&](int a) {
    return std::array<int, 2>{std::max(lo, (*box)[0][a] - samples.origin[a]),
                              std::min(hi, (*box)[1][a] - samples.origin[a])};
  };
  const std::array<int, 2> x = insideRange(0), y = insideRange(1), z = insideRange(2);
  for (int k = lo; k <= hi; ++k)
    for (int j = lo; j <= hi; ++j) {
      float* row = &samples.values[samples.indexOf(lo, j, k)];
      if (k < z[0] || k > z[1] || j < y[0] || j > y[1] || x[0] > x[1]) {
        std::fill(row, row + (hi - lo + 1), far);  // the whole row lies beyond the box
        continue;
      }
      std::fill(row, row + (x[0] - lo), far);                      // before the box along x
      std::fill(row + (x[1] - lo + 1), row + (hi - lo + 1), far);  // after it
    }
}

/// The box beyond which the contouring reads far outside (set by extract for adaptive mode
/// and regular mode in Wenger's reading, and the voxel reading where the background lies
/// inside; the voxel reading's other caps are made on the field as it is,
/// cell::ContourSettings::capBox).
std::optional<volume::IndexBox> capsIndexBox(const cell::ContourSettings& settings) {
  if (!settings.dataBox) return std::nullopt;
  return volume::IndexBox{(*settings.dataBox)[0], (*settings.dataBox)[1]};
}

/// The engine's inside is value <= iso; a scalar's inside is above the isovalue. Returns
/// the iso the engine reads the block at, after the data box's caps are set up.
float engineIso(volume::VolumeKind kind, float iso, const Engine& engine, cell::MetaCellSamples& samples) {
  if (kind == volume::VolumeKind::Scalar) {
    for (float& v : samples.values) v = -v;
    iso = -iso;
  }
  farOutsideBeyondDataBox(samples, iso, engine.valueBound, engine.settings.dataBox);
  return iso;
}

void recordTotals(const MetaCellTotals& totals, const cell::ContourSettings& options, Statistics::Json& section) {
  const bool byEdges = options.contoursByMinimalEdges();
  const contour::RegularContourStats& r = totals.regular;
  const contour::AdaptiveContourStats& a = totals.adaptive;
  section["leaves"] = totals.leaves;
  section["complex_cells"] = totals.build.complexCells;
  section["unresolved_complex_leaves"] = totals.build.unresolvedComplexLeaves;
  section["boundary_cells_kept"] = byEdges ? a.seamCells : r.seamCells;
  section["edges_left_to_stitching"] = byEdges ? a.boundaryEdges : r.boundaryEdges;
  section["manifold_fixes"] = byEdges ? a.manifoldFixes : r.manifoldFixes;
  if (byEdges) {
    section["intersection_free"] = options.intersectionFree;
    section["multi_vertex_cells"] = a.multiVertexCells;
    section["voxel_reading_edges"] = a.voxelEdges;
    section["minimal_edges"] = a.minimalEdges;
    section["fanned_edges"] = a.fannedEdges;
    section["triangles_added_by_fans"] = a.trianglesAddedByFans;
  }
  if (options.method == cell::ContourMethod::Regular) {
    section["topology"] = std::string(cell::regularTopologyName(options.topology));
    if (!byEdges) section["manifold_fixes_beyond_apron"] = r.fixesBeyondApron;
    if (options.topology == cell::RegularTopology::Voxels) section["tube_cells"] = r.tubeCells;
  } else {
    section["geometric_splits"] = totals.build.geometricSplits;
    section["error_bound_splits"] = totals.build.errorBoundSplits;
    section["error_bound_passes"] = totals.errorBoundPasses;
    section["error_bound_leaves_split"] = totals.errorBoundLeavesSplit;
    section["multi_sheet_splits"] = totals.build.multiSheetSplits;
    section["data_box_splits"] = totals.build.dataBoxSplits;
    section["hidden_component_splits"] = totals.build.hiddenComponentSplits;
    section["sharp_features"] = options.sharpFeatures;
  }
  section["cpu_seconds_read"] = totals.readSeconds;
  section["cpu_seconds_octree"] = totals.octreeSeconds;
  section["cpu_seconds_contour"] = totals.contourSeconds;
  section["cpu_seconds_error_bound"] = totals.errorBoundSeconds;
}

/// One padded meta-cell around the whole band (no seams).
void contourSingleBlock(const volume::Volume& field, const Engine& engine, mesh::MeshSink& sink,
                        Interrupter* interrupter, Statistics* stats) {
  openvdb::CoordBBox band;
  const bool active = volume::fieldGrid(field).tree().evalActiveVoxelBoundingBox(band);
  // Where the background is inside, caps may close regions without a voxel: the block spans the box.
  if (const auto box = capsIndexBox(engine.settings); box && volume::backgroundInside(field, engine.settings.iso))
    band.expand(openvdb::CoordBBox(openvdb::Coord(box->min[0], box->min[1], box->min[2]),
                                   openvdb::Coord(box->max[0], box->max[1], box->max[2])));
  else if (!active)
    return;
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
    iso = engineIso(field.kind(), iso, engine, samples);
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
  return std::max(1, octree::finestLeafSize(engine.tree, engine.metaCellSize));
}

/// One meta-cell's result on its way through the pipeline.
struct MetaCellJob {
  std::size_t position = 0;
  bool contoured = false;  ///< its samples change sign
  contour::MetaCellMesh result;
  MetaCellTotals totals;
};

void checkMetaCellSize(int s) {
  if (s < 16 || s > 512 || (s & (s - 1)) != 0)
    throw InputError("--meta-cell: expected a power of two in 16..512 (or 0 for one block), got " + std::to_string(s));
}

/// Meta-cells contoured in parallel, handed to the consumer in the order given (a
/// SeamedMeshAssembler: meshes into the sink, seams kept). Batches of meta-cells (all
/// of them, or one layer at a time) are contoured one after the other.
class MetaCellRun {
 public:
  /// Fills a meta-cell's samples; called from several threads at once.
  using Reader = std::function<void(const volume::MetaCellIndex&, cell::MetaCellSamples&)>;

  MetaCellRun(const Engine& engine, volume::VolumeKind kind, MetaCellConsumer& consumer)
      : engine_(engine),
        kind_(kind),
        consumer_(consumer),
        threads_(std::max<std::size_t>(
            1, tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism))) {}

  /// Contours `cells` (in this order), reporting each one done to `cellDone`.
  void contour(const std::vector<volume::MetaCellIndex>& cells, const Reader& read,
               const std::function<void()>& cellDone) {
    const cell::ContourSettings& options = engine_.settings;
    std::size_t next = 0;
    candidates_ += cells.size();
    // The jobs are owned here, not by the pipeline's tokens: when a filter throws
    // (Ctrl-C through cellDone, a bad block) TBB cancels the tokens in flight without
    // destroying them, so an item type that owns memory would leak its meta-cell's mesh.
    std::vector<std::unique_ptr<MetaCellJob>> jobs(cells.size());
    tbb::parallel_pipeline(
        kTokensPerThread * threads_,
        tbb::make_filter<void, MetaCellJob*>(tbb::filter_mode::serial_in_order,
                                             [&](tbb::flow_control& control) -> MetaCellJob* {
                                               if (next >= cells.size()) {
                                                 control.stop();
                                                 return nullptr;
                                               }
                                               jobs[next] = std::make_unique<MetaCellJob>();
                                               jobs[next]->position = next;
                                               return jobs[next++].get();
                                             }) &
            tbb::make_filter<MetaCellJob*, MetaCellJob*>(
                tbb::filter_mode::parallel,
                [&](MetaCellJob* job) {
                  // Isolated: a thread waiting in this block's parallel loops must not take up
                  // another block meanwhile, which would fill this thread's samples, still in use.
                  tbb::this_task_arena::isolate([&] {
                    const auto t0 = std::chrono::steady_clock::now();
                    cell::MetaCellSamples& samples = sampleBlocks_.local();
                    read(cells[job->position], samples);
                    const float iso = engineIso(kind_, options.iso, engine_, samples);
                    job->totals.readSeconds += secondsSince(t0);
                    // The phases tell whether the level crosses the block, and the tree, the
                    // crossings and the error bound read them (hasSignChange was one more
                    // pass over the block's floats).
                    const auto t1 = std::chrono::steady_clock::now();
                    const octree::SamplePhases phases(samples, iso);
                    job->totals.octreeSeconds += secondsSince(t1);
                    job->contoured = phases.boxPhase({0, 0, 0}, samples.size + 1) < 0;
                    if (job->contoured)
                      job->result = contourBlock(samples, engine_, iso, job->totals, nullptr, nullptr, &phases);
                  });
                  return job;
                }) &
            tbb::make_filter<MetaCellJob*, void>(tbb::filter_mode::serial_in_order, [&](MetaCellJob* job) {
              totals_.add(job->totals);
              if (job->contoured) {
                ++contoured_;
                consumer_.add(cells[job->position], std::move(job->result));
              }
              jobs[job->position].reset();  // its mesh is with the consumer now
              cellDone();
            }));
  }

  /// Records the figures of the meta-cells contoured.
  void record(int apron, std::int64_t leavesScanned, Statistics* stats) const {
    const cell::ContourSettings& options = engine_.settings;
    if (!stats) return;
    Statistics::Json section = Statistics::Json::object();
    section["meta_cell_size"] = engine_.metaCellSize;
    section["apron"] = apron;
    section["threads"] = threads_;
    section["candidates"] = candidates_;
    section["contoured"] = contoured_;
    section["skipped_without_sign_change"] = candidates_ - contoured_;
    section["leaves_scanned_for_partition"] = leavesScanned;
    recordTotals(totals_, options, section);
    (*stats)["meta_cells"] = section;
  }

 private:
  const Engine& engine_;
  volume::VolumeKind kind_;
  MetaCellConsumer& consumer_;
  std::size_t threads_;
  MetaCellTotals totals_;
  std::size_t candidates_ = 0, contoured_ = 0;
  // One sample block per thread, reused meta-cell after meta-cell: a fresh 9 MB
  // block per meta-cell had every page faulted in again.
  tbb::enumerable_thread_specific<cell::MetaCellSamples> sampleBlocks_;
};

/// Every meta-cell (of `layers`, when set) in parallel, to the consumer in meta-cell order.
void contourMetaCells(const volume::Volume& field, const Engine& engine, MetaCellConsumer& consumer,
                      const std::optional<MetaCellLayers>& layers, Interrupter* interrupter, Statistics* stats) {
  const int s = engine.metaCellSize;
  checkMetaCellSize(s);
  volume::MetaCellPartition partition;
  {
    Statistics::StageTimer timer(stats, "partition");
    partition = volume::partitionMetaCells(field, s, engine.settings.iso, capsIndexBox(engine.settings));
    if (layers) std::erase_if(partition.cells, [&](const volume::MetaCellIndex& c) { return !layers->contains(c[2]); });
  }
  const int apron = metaCellApron(engine);
  MetaCellRun run(engine, field.kind(), consumer);
  {
    Statistics::StageTimer timer(stats, "contour_meta_cells");
    ProgressStage progress(interrupter, "contouring meta-cells");
    std::size_t done = 0;
    const auto total = static_cast<double>(partition.cells.size());
    run.contour(
        partition.cells,
        [&](const volume::MetaCellIndex& index, cell::MetaCellSamples& samples) {
          volume::readMetaCell(field, index, s, samples, apron);
        },
        [&] { progress.update(static_cast<double>(++done), total); });
  }
  run.record(apron, partition.leavesScanned, stats);
}

/// A mask's meta-cells layer by layer, each layer's distance field computed just
/// before it is contoured (volume/slab_band.h): the same meshes as contourMetaCells
/// on distanceField(mask), without the whole band in memory.
void contourMaskMetaCells(const volume::Volume& mask, const volume::DistanceFieldOptions& distance,
                          const Engine& engine, MetaCellConsumer& consumer, const std::optional<MetaCellLayers>& layers,
                          Interrupter* interrupter, Statistics* stats) {
  const int s = engine.metaCellSize;
  checkMetaCellSize(s);
  const int apron = metaCellApron(engine);
  std::optional<volume::SlabBand> band;
  {
    Statistics::StageTimer timer(stats, "distance_field");
    band.emplace(mask, distance, s, apron);
  }
  MetaCellRun run(engine, volume::VolumeKind::DistanceField, consumer);
  ProgressStage progress(interrupter, "contouring meta-cells");
  const int first = layers ? std::max(layers->begin, band->firstLayer()) : band->firstLayer();
  const int end = layers ? std::min(layers->end, band->endLayer()) : band->endLayer();
  const int count = std::max(0, end - first);
  for (int k = first; k < end; ++k) {
    const double layer = k - first;
    std::vector<volume::MetaCellIndex> cells;
    {
      // The band's chunks report the layer's start again: Ctrl-C is noticed within a layer's band.
      Statistics::StageTimer timer(stats, "distance_field");
      cells = band->advanceTo(k, engine.settings.iso, [&] { progress.update(layer, count); });
    }
    Statistics::StageTimer timer(stats, "contour_meta_cells");
    std::size_t done = 0;
    run.contour(
        cells, [&](const volume::MetaCellIndex& index, cell::MetaCellSamples& samples) { band->read(index, samples); },
        [&] { progress.update(layer + static_cast<double>(++done) / static_cast<double>(cells.size()), count); });
    progress.update(layer + 1, count);
  }
  if (stats) {
    Statistics::Json section = distanceFieldSection(distance);
    recordBandFigures(band->figures(), mask.geometry(), section);
    section["computed_by_meta_cell_layer"] = true;
    section["peak_band_memory_bytes"] = band->figures().peakBytes;
    (*stats)["distance_field"] = section;
  }
  band.reset();
  run.record(apron, 0, stats);
}

void checkOctreeMethod(const cell::ContourSettings& settings) {
  if (settings.method == cell::ContourMethod::Vdb)
    throw InputError("octree contouring: the method is vdb; expected regular or adaptive");
}

}  // namespace

void contourWithOctree(const volume::Volume& field, const cell::ContourSettings& settings,
                       const octree::OctreeOptions& tree, int metaCellSize, mesh::MeshSink& sink,
                       Interrupter* interrupter, Statistics* stats) {
  if (field.kind() == volume::VolumeKind::Mask)
    throw InputError("'" + field.name() + "': octree contouring needs a distance field or a scalar field");
  checkOctreeMethod(settings);
  const Engine engine{settings, tree, metaCellSize, valueBound(field)};
  if (metaCellSize == 0) {
    contourSingleBlock(field, engine, sink, interrupter, stats);
    return;
  }
  SeamedMeshAssembler assembler(settings, metaCellSize, sink);
  contourMetaCells(field, engine, assembler, std::nullopt, interrupter, stats);
  assembler.finish(interrupter, stats);
}

void contourMetaCellsInto(const volume::Volume& field, const cell::ContourSettings& settings,
                          const octree::OctreeOptions& tree, int metaCellSize, MetaCellConsumer& consumer,
                          const std::optional<MetaCellLayers>& layers, std::optional<float> bound,
                          Interrupter* interrupter, Statistics* stats) {
  if (field.kind() == volume::VolumeKind::Mask)
    throw InputError("'" + field.name() + "': octree contouring needs a distance field or a scalar field");
  checkOctreeMethod(settings);
  const Engine engine{settings, tree, metaCellSize, bound ? *bound : valueBound(field)};
  contourMetaCells(field, engine, consumer, layers, interrupter, stats);
}

void SeamedMeshAssembler::add(const volume::MetaCellIndex& index, contour::MetaCellMesh&& block) {
  const auto base = static_cast<std::uint32_t>(sink_.vertexCount());
  for (mesh::Triangle& t : block.mesh.triangles)
    for (std::uint32_t& v : t) v += base;
  sink_.addVertices(block.mesh.positions);
  sink_.addTriangles(block.mesh.triangles);
  contour::rebaseSeam(block.seam, base);
  stitcher_.add(index, std::move(block.seam));
}

void SeamedMeshAssembler::finish(Interrupter* interrupter, Statistics* stats) {
  {
    Statistics::StageTimer timer(stats, "stitch");
    mesh::Mesh tail;
    stitcher_.finish(static_cast<std::uint32_t>(sink_.vertexCount()), tail, interrupter);
    sink_.addVertices(tail.positions);
    sink_.addTriangles(tail.triangles);
  }
  if (!stats) return;
  const stitch::StitchStats& figures = stitcher_.stats();
  Statistics::Json st = Statistics::Json::object();
  st["meta_faces"] = figures.metaFaces;
  st["meta_edges"] = figures.metaEdges;
  st["seam_cells"] = figures.seamCells;
  st["peak_held_seam_cells"] = figures.peakHeldCells;
  st["edges"] = figures.edges;
  if (stitcher_.settings().contoursByMinimalEdges()) st["fanned_edges"] = figures.fannedEdges;
  st["missing_cells"] = figures.missingCells;
  (*stats)["stitch"] = st;
}

octree::LinearOctree metaCellOctree(const volume::Volume& field, const cell::ContourSettings& settings,
                                    const octree::OctreeOptions& tree, int metaCellSize,
                                    const std::array<int, 3>& index, octree::OctreeBuildStats* stats,
                                    bool* hasSignChange, Interrupter* interrupter) {
  const Engine engine{settings, tree, metaCellSize, valueBound(field)};
  cell::MetaCellSamples samples;
  volume::readMetaCell(field, index, metaCellSize, samples, metaCellApron(engine));
  cell::ContourSettings blockSettings = settings;
  blockSettings.iso = engineIso(field.kind(), settings.iso, engine, samples);
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

void contourMaskWithOctree(const volume::Volume& mask, const volume::DistanceFieldOptions& distance,
                           const cell::ContourSettings& settings, const octree::OctreeOptions& tree, int metaCellSize,
                           mesh::MeshSink& sink, Interrupter* interrupter, Statistics* stats) {
  SeamedMeshAssembler assembler(settings, metaCellSize, sink);
  contourMaskMetaCellsInto(mask, distance, settings, tree, metaCellSize, assembler, std::nullopt, interrupter, stats);
  assembler.finish(interrupter, stats);
}

void contourMaskMetaCellsInto(const volume::Volume& mask, const volume::DistanceFieldOptions& distance,
                              const cell::ContourSettings& settings, const octree::OctreeOptions& tree,
                              int metaCellSize, MetaCellConsumer& consumer, const std::optional<MetaCellLayers>& layers,
                              Interrupter* interrupter, Statistics* stats) {
  if (mask.kind() != volume::VolumeKind::Mask)
    throw InputError("'" + mask.name() + "': contouring by meta-cell layers needs a mask");
  if (distance.method != volume::DistanceMethod::Interface)
    throw InputError("contouring by meta-cell layers: the distance field must be the interface band");
  checkOctreeMethod(settings);
  // The band's samples are distances in voxels, ±halfWidth beyond it.
  const Engine engine{settings, tree, metaCellSize, static_cast<float>(distance.halfWidth)};
  contourMaskMetaCells(mask, distance, engine, consumer, layers, interrupter, stats);
}

mesh::Mesh contourWithOctree(const volume::Volume& field, const cell::ContourSettings& settings,
                             const octree::OctreeOptions& tree, int metaCellSize, Interrupter* interrupter,
                             Statistics* stats) {
  mesh::MeshCollector collector;
  contourWithOctree(field, settings, tree, metaCellSize, collector, interrupter, stats);
  return std::move(collector.mesh);
}

}  // namespace isovdb::pipeline
