// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/octree/build.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <string>
#include <utility>

#include "isovdb/bit_count.h"
#include "isovdb/cell/dmc_table.h"
#include "isovdb/cell/dual_vertex.h"
#include "isovdb/cell/trilinear.h"
#include "isovdb/errors.h"
#include "isovdb/octree/criteria.h"
#include "isovdb/octree/surface_deviation.h"
#include "isovdb/octree/surface_gap.h"
#include "isovdb/octree/unit_edge_crossings.h"

namespace isovdb::octree {

namespace {

/// Open-addressing hash map MortonKey -> int32 (linear probing, no erase).
class KeyMap {
 public:
  explicit KeyMap(std::size_t expected = 1024) { rehash(std::bit_ceil(expected * 2 + 16)); }

  std::int32_t* find(MortonKey key) noexcept {
    for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
      if (keys_[i] == key) return &values_[i];
      if (keys_[i] == kInvalidKey) return nullptr;
    }
  }
  void assign(MortonKey key, std::int32_t value) {
    if ((count_ + 1) * 2 > keys_.size()) rehash(keys_.size() * 2);
    std::size_t i = slot(key);
    while (keys_[i] != kInvalidKey && keys_[i] != key) i = (i + 1) & mask_;
    if (keys_[i] == kInvalidKey) ++count_;
    keys_[i] = key;
    values_[i] = value;
  }

 private:
  std::size_t slot(MortonKey key) const noexcept {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 20) & mask_;
  }
  void rehash(std::size_t capacity) {
    std::vector<MortonKey> oldKeys = std::move(keys_);
    std::vector<std::int32_t> oldValues = std::move(values_);
    keys_.assign(capacity, kInvalidKey);
    values_.assign(capacity, 0);
    mask_ = capacity - 1;
    count_ = 0;
    for (std::size_t i = 0; i < oldKeys.size(); ++i)
      if (oldKeys[i] != kInvalidKey) assign(oldKeys[i], oldValues[i]);
  }
  std::vector<MortonKey> keys_;
  std::vector<std::int32_t> values_;
  std::size_t mask_ = 0;
  std::size_t count_ = 0;
};

constexpr std::int32_t kInternal = -1;

/// One bit per node of each shallow depth, set once the node is internal (split): what
/// balancing asks of every internal node's 7 neighbours on its side, millions of times in
/// a surface-heavy block. Indexed by the key's Morton bits, so neighbours are near; the
/// hash map's slots are not. Depths whose bits would take more than kMaxBytes (meta-cells
/// of 1024 voxels and more) are left to the map.
class InternalNodeBits {
 public:
  void mark(MortonKey key) {
    const int depth = keyDepth(key);
    if (depth > kMaxDepth) return;
    if (bits_.size() <= static_cast<std::size_t>(depth)) bits_.resize(static_cast<std::size_t>(depth) + 1);
    std::vector<std::uint64_t>& words = bits_[static_cast<std::size_t>(depth)];
    if (words.empty()) words.assign((std::size_t{1} << (3 * depth)) / 64 + 1, 0);
    const std::uint64_t i = key ^ (MortonKey{1} << (3 * depth));
    words[i >> 6] |= std::uint64_t{1} << (i & 63);
  }
  /// True if `key` was marked (false may still be internal, at a depth left to the map).
  bool holds(MortonKey key) const noexcept {
    const auto depth = static_cast<std::size_t>(keyDepth(key));
    if (depth >= bits_.size() || bits_[depth].empty()) return false;
    const std::uint64_t i = key ^ (MortonKey{1} << (3 * depth));
    return (bits_[depth][i >> 6] >> (i & 63)) & 1;
  }

 private:
  static constexpr std::size_t kMaxBytes = std::size_t{1} << 21;
  static constexpr int kMaxDepth = 8;  // 8^8 bits = 2 MiB = kMaxBytes
  static_assert((std::size_t{1} << (3 * kMaxDepth)) / 8 == kMaxBytes);
  std::vector<std::vector<std::uint64_t>> bits_;
};

/// Crossing normals farther apart than this (cosine: 60 degrees) mark a leaf on a sharp
/// feature, whose vertex the sharp-feature gap checks (a smooth leaf's planes are close).
constexpr float kFeatureCone = 0.5f;

/// Result of evaluating one cell.
struct Evaluation {
  OctreeLeaf leaf;
  bool split = false;
  bool classified = false;
  bool complex = false;
  bool geometric = false;   // split only because of the QEF criterion
  bool feature = false;     // of those, because of the sharp-feature gap
  bool bounded = false;     // of those, because of the error bound (--max-error)
  bool capped = false;      // split because it lies across a face of the data's box (adaptive)
  bool multiSheet = false;  // split only because one vertex cannot stand for the cell (adaptive)
  bool hidden = false;      // split only because of a component hidden inside (adaptive)
  bool interiorOnly = false;
  std::uint8_t complexEdges = 0;
  std::uint8_t complexFaces = 0;
};

}  // namespace

struct BuildMemo::Impl {
  /// A build's evaluations are kept as they come (a whole level's vector at a time) and
  /// indexed only when a next build starts: most blocks are built once.
  std::vector<std::vector<Evaluation>> unindexed;
  std::vector<Evaluation> loose;  // the balancing's, one at a time
  std::vector<Evaluation> indexed;
  KeyMap index;  // key -> position in indexed

  void prepare() {
    unindexed.push_back(std::move(loose));
    loose.clear();
    for (const std::vector<Evaluation>& batch : unindexed)
      for (const Evaluation& ev : batch) {
        if (index.find(ev.leaf.key)) continue;  // recalled
        index.assign(ev.leaf.key, static_cast<std::int32_t>(indexed.size()));
        indexed.push_back(ev);
      }
    unindexed.clear();
  }
  const Evaluation* find(MortonKey key) noexcept {
    const std::int32_t* i = index.find(key);
    return i ? &indexed[static_cast<std::size_t>(*i)] : nullptr;
  }
};

BuildMemo::BuildMemo() : impl_(std::make_unique<Impl>()) {}
BuildMemo::~BuildMemo() = default;

namespace {

class Builder {
 public:
  Builder(const cell::MetaCellSamples& samples, const cell::ContourSettings& settings, const OctreeOptions& options,
          OctreeDepths depths, const UnitEdgeCrossings* crossings, const SamplePhases* phases, BuildMemo* memo)
      : samples_(samples),
        settings_(settings),
        options_(options),
        depths_(depths),
        crossings_(crossings),
        ownPhases_(phases ? std::nullopt : std::optional<SamplePhases>(std::in_place, samples, settings.iso)),
        phases_(phases ? *phases : *ownPhases_),
        memo_(memo ? &memo->impl() : nullptr),
        leavesAtDepth_(static_cast<std::size_t>(depths.maxDepth) + 1) {
    classify_.detectInteriorComponents = options.detectInteriorComponents;
    if (memo_) memo_->prepare();
    if (settings.adaptiveReadsVoxels() && depths.maxDepth == depthForCellSize(samples.size, 1)) markVoxelReadingCells();
  }

  /// The memo's evaluation of `key` (not for a forced split: an earlier build kept that
  /// cell a leaf), else a new one. Safe in parallel: the memo's index is read only.
  Evaluation recallOrEvaluate(MortonKey key, FaceLabeller& labeller) const {
    if (memo_ && !isForcedSplit(key))
      if (const Evaluation* ev = memo_->find(key)) return *ev;
    return evaluate(key, labeller);
  }

  /// recallOrEvaluate, kept for the next build (one thread at a time).
  Evaluation evaluateOnce(MortonKey key, FaceLabeller& labeller) {
    const Evaluation ev = recallOrEvaluate(key, labeller);
    if (memo_ && ev.leaf.size > 1) memo_->loose.push_back(ev);  // unit cells: see BuildMemo
    return ev;
  }

  bool isForcedSplit(MortonKey key) const {
    return !options_.forcedSplits.empty() &&
           std::binary_search(options_.forcedSplits.begin(), options_.forcedSplits.end(), key);
  }

  Evaluation evaluate(MortonKey key, FaceLabeller& labeller) const {
    Evaluation ev;
    const KeyCoord c = decodeKey(key);
    const int size = samples_.size >> c.depth;
    ev.leaf.key = key;
    ev.leaf.depth = static_cast<std::uint8_t>(c.depth);
    ev.leaf.size = size;
    ev.leaf.origin = {c.xyz[0] * size, c.xyz[1] * size, c.xyz[2] * size};
    if (c.depth < depths_.minDepth) {
      ev.split = true;
      return ev;
    }
    if (c.depth < depths_.maxDepth && isForcedSplit(key)) {
      ev.split = true;
      return ev;
    }
    if (c.depth < depths_.maxDepth && !voxelSplits_.empty() && voxelSplit(c)) {
      ev.split = true;
      return ev;
    }
    if (settings_.method == cell::ContourMethod::Regular && c.depth < depths_.maxDepth &&
        options_.detectInteriorComponents) {
      // The regular construction refines every cell the surface crosses down to the
      // maximum depth, complex or not, so above it the criteria have nothing to
      // decide: one pass over the cell's sample bits says whether it is crossed.
      ev.leaf.cornerSigns = cellCornerSigns(phases_, ev.leaf.origin, size);
      ev.leaf.surface = ev.split = phases_.boxPhase(ev.leaf.origin, size + 1) < 0;
      return ev;
    }
    ev.classified = true;
    const CellTopology topo = classifyCell(phases_, ev.leaf.origin, size, classify_, labeller);
    ev.leaf.cornerSigns = topo.cornerSigns;
    ev.leaf.surface = topo.isHeterogeneous();
    ev.complex = topo.isComplex();
    ev.interiorOnly = ev.complex && topo.complexEdges == 0 && topo.complexFaces == 0;
    ev.complexEdges = static_cast<std::uint8_t>(countBits(topo.complexEdges));
    ev.complexFaces = static_cast<std::uint8_t>(countBits(topo.complexFaces));
    const bool canSplit = c.depth < depths_.maxDepth;
    if (!canSplit) {
      ev.leaf.complex = ev.complex;
      return ev;
    }
    if (ev.complex) {
      ev.split = true;
    } else if (settings_.method == cell::ContourMethod::Regular) {
      ev.split = ev.leaf.surface;
    } else if (ev.leaf.surface && crossesDataBoxFace(ev.leaf.origin, size)) {
      ev.split = ev.capped = true;
    } else if (const cell::DmcEntry& entry = cell::dmcEntry(ev.leaf.cornerSigns);
               entry.vertexCount > 1 || entry.doubleFace >= 0) {
      // Dual contouring gives a coarse leaf one vertex: a configuration with several
      // sheets (DMC groups) or one sheet through an ambiguous face twice would make it
      // non-manifold, so such cells are refined; at the maximum depth each group
      // gets its vertex (contour/leaf_groups.h).
      ev.split = ev.multiSheet = true;
    } else if ((options_.qefTolerance >= 0.0f || options_.maxError > 0.0f) && ev.leaf.surface) {
      const cell::DualVertex v = cellDualVertex(samples_, ev.leaf.origin, size, ev.leaf.bipolarEdges(),
                                                cell::dualVertexOptions(settings_), crossings_);
      // With a bound, the leaves whose triangles the block makes are held by the bound's
      // check after contouring; those whose face on the meta-cell's boundary the surface
      // crosses (their seam triangles are stitched later, unchecked) by the plane test below
      // and by this QEF share, which a thin structure beside a seam needs (kBoundedQefShare):
      // so the share applies with the criterion turned off too. Two-voxel leaves touching
      // the boundary keep the seam's share: with the looser one, the check's passes left the
      // 64^3 genus-2 (seams of 32, E = 0.25) more triangles than regular mode.
      const float qefTolerance = options_.maxError > 0.0f
                                     ? std::max(options_.qefTolerance, kBoundedQefShare * options_.maxError)
                                     : options_.qefTolerance;
      ev.split = ev.geometric = v.valid() && qefTolerance >= 0.0f && v.rmsError() > qefTolerance;
      if (!ev.split && v.valid() && options_.maxError > 0.0f) {
        const Vec3f x = toMetaCellOffsets(v.position);
        const bool onSeam = size <= 2 ? touchesMetaCellBoundary(ev.leaf.origin, size, samples_.size)
                                      : crossesMetaCellBoundary(phases_, ev.leaf.origin, size);
        // On the seam the margin the check keeps is kept here.
        const float reach = options_.maxError - kErrorBoundMargin;  // what the check allows
        const float allowed = onSeam ? kPlaneShare * options_.maxError - kErrorBoundMargin
                              : size <= 2
                                  ? std::max(kPlaneShare * options_.maxError, options_.maxError - kTwoVoxelReserve)
                                  : kInteriorPlaneShare * options_.maxError;
        ev.split = ev.geometric = ev.bounded =
            surfaceDeviatesBeyond(samples_, phases_, ev.leaf.origin, size, x, settings_.iso, allowed) ||
            // The check measures every vertex of the mesh against the level as this does: a
            // vertex it would find beyond costs a pass, which builds the whole block again.
            !cell::levelWithin(samples_, x, cell::dualVertexOptions(settings_), reach);
      }
      if (!ev.split && settings_.sharpFeatures && v.valid() && v.minNormalDot < kFeatureCone) {
        // A few tangent planes of a curved crease meet off it while fitting almost exactly.
        const Vec3f x = toMetaCellOffsets(v.position);
        ev.split = ev.geometric = ev.feature =
            surfaceGap(samples_, ev.leaf.origin, size, x, settings_.iso) > options_.featureTolerance;
      }
      if (v.valid()) {
        ev.leaf.vertex = v.position;
        ev.leaf.vertexTruncation = settings_.singularValueThreshold;
        ev.leaf.vertexSharpFeatures = settings_.sharpFeatures;
      }
    }
    // A leaf-to-be of the adaptive tree whose faces the surface crosses may still hide a
    // bubble or a speck inside (the criteria only look at edges and faces; a cell with
    // one-phase faces was scanned by classifyCell already).
    if (!ev.split && settings_.method == cell::ContourMethod::Adaptive && options_.detectInteriorComponents &&
        !topo.boundaryUniform && ev.leaf.surface && hasHiddenComponent(phases_, ev.leaf.origin, size))
      ev.split = ev.hidden = true;
    return ev;
  }

  /// The cell [origin, origin + size] (meta-cell offsets) reaches past a face of the data's
  /// box, from the face's plane on: it holds samples on both sides of it, or lies just beyond.
  bool crossesDataBoxFace(const std::array<int, 3>& origin, int size) const noexcept {
    if (!settings_.dataBox || size <= 1) return false;
    for (int a = 0; a < 3; ++a) {
      const int lo = origin[a] + samples_.origin[a], hi = lo + size;
      if (lo < (*settings_.dataBox)[0][a] && hi >= (*settings_.dataBox)[0][a]) return true;
      if (lo <= (*settings_.dataBox)[1][a] && hi > (*settings_.dataBox)[1][a]) return true;
    }
    return false;
  }

  Vec3f toMetaCellOffsets(const Vec3f& global) const noexcept {
    return {global[0] - static_cast<float>(samples_.origin[0]), global[1] - static_cast<float>(samples_.origin[1]),
            global[2] - static_cast<float>(samples_.origin[2])};
  }

  void count(const Evaluation& ev) {
    if (!ev.classified) return;
    ++stats_.cellsClassified[ev.leaf.depth];
    stats_.complexEdges += ev.complexEdges;
    stats_.complexFaces += ev.complexFaces;
    stats_.interiorComponents += ev.interiorOnly;
    stats_.complexCells += ev.complex;
    stats_.geometricSplits += ev.geometric;
    stats_.featureSplits += ev.feature;
    stats_.errorBoundSplits += ev.bounded;
    stats_.dataBoxSplits += ev.capped;
    stats_.multiSheetSplits += ev.multiSheet;
    stats_.hiddenComponentSplits += ev.hidden;
  }

  /// Level-by-level top-down construction; each level's cells are evaluated in parallel.
  void buildTopDown(Interrupter* interrupter) {
    stats_.cellsClassified.assign(static_cast<std::size_t>(depths_.maxDepth) + 1, 0);
    const ProgressStage progress(interrupter, "octree");
    std::vector<MortonKey> level{kRootKey};
    std::vector<Evaluation> evals;
    tbb::enumerable_thread_specific<FaceLabeller> labellers;
    for (int depth = 0; !level.empty(); ++depth) {
      progress.update(depth, depths_.maxDepth + 1);
      evals.resize(level.size());
      auto body = [&](const tbb::blocked_range<std::size_t>& r) {
        FaceLabeller& labeller = labellers.local();
        for (std::size_t i = r.begin(); i != r.end(); ++i) evals[i] = recallOrEvaluate(level[i], labeller);
      };
      const tbb::blocked_range<std::size_t> range(0, level.size(), 16);
      if (options_.parallel && level.size() > 1)
        tbb::parallel_for(range, body);
      else
        body(range);
      std::vector<MortonKey> next;
      for (const Evaluation& ev : evals) {
        count(ev);
        if (ev.split) {
          markInternal(ev.leaf.key);
          for (int o = 0; o < 8; ++o) next.push_back(childKey(ev.leaf.key, o));
        } else {
          addLeaf(ev);
        }
      }
      if (memo_ && (samples_.size >> depth) > 1) memo_->unindexed.push_back(std::exchange(evals, {}));
      level.swap(next);
    }
  }

  /// Splits leaf record `index` and evaluates its children; children that want
  /// a split are refined recursively. Returns nothing; records are appended.
  void splitLeaf(std::int32_t index, FaceLabeller& labeller) {
    std::vector<MortonKey> stack;
    const MortonKey key = records_[static_cast<std::size_t>(index)].key;
    alive_[static_cast<std::size_t>(index)] = false;
    markInternal(key);
    for (int o = 7; o >= 0; --o) stack.push_back(childKey(key, o));
    while (!stack.empty()) {
      const MortonKey k = stack.back();
      stack.pop_back();
      const Evaluation ev = evaluateOnce(k, labeller);
      count(ev);
      if (ev.split) {
        markInternal(k);
        for (int o = 7; o >= 0; --o) stack.push_back(childKey(k, o));
      } else {
        addLeaf(ev);
      }
    }
  }

  /// Restores 2:1 balance over faces, edges and corners, refining complex
  /// children created on the way, until nothing changes.
  ///
  /// Leaves that share a face, an edge or a corner differ by at most one depth
  /// iff every internal node's 26 same-size neighbours exist (their parents are
  /// internal): a leaf's neighbours lie in its parent's neighbourhood, and an
  /// internal node has a child beside each of its neighbours. Checking the
  /// internal nodes costs an eighth of checking the leaves. Deepest first: a
  /// split only creates nodes at the split leaf's depth or above, so one pass
  /// from the bottom up balances the tree.
  void balance(Interrupter* interrupter) {
    FaceLabeller labeller;
    const ProgressStage progress(interrupter, "octree balance");
    bool changed = true;
    while (changed) {
      changed = false;
      std::vector<MortonKey> internal;  // internal nodes one depth below the current one
      for (int depth = depths_.maxDepth - 1; depth >= 2; --depth) {
        progress.update(depths_.maxDepth - 1 - depth, depths_.maxDepth);
        // Internal nodes at `depth`: parents of the leaves and internal nodes one depth below.
        std::vector<MortonKey> nodes;
        nodes.reserve(internal.size() + leavesAtDepth_[static_cast<std::size_t>(depth) + 1].size() / 8 + 1);
        for (const MortonKey k : internal) nodes.push_back(parentKey(k));
        for (const DepthLeaf& l : leavesAtDepth_[static_cast<std::size_t>(depth) + 1])
          if (alive_[static_cast<std::size_t>(l.index)]) nodes.push_back(parentKey(l.key));
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        for (const MortonKey node : nodes) {
          // The parents of node's 26 neighbours are its parent and the parent's 7 neighbours
          // on node's side of it (one step towards each axis where node lies in the parent):
          // 7 lookups where walking the 26 neighbours made 26, 19 of them repeated.
          const MortonKey parent = parentKey(node);
          const int octant = octantOf(node);
          const int sx = (octant & 1) ? 1 : -1, sy = (octant & 2) ? 1 : -1, sz = (octant & 4) ? 1 : -1;
          for (int side = 1; side < 8; ++side) {
            const MortonKey target =
                neighbourKey(parent, (side & 1) ? sx : 0, (side & 2) ? sy : 0, (side & 4) ? sz : 0);
            if (target == kInvalidKey || internal_.holds(target)) continue;
            // Split the leaf that covers the target until the target is internal.
            for (;;) {
              MortonKey a = target;
              std::int32_t* v = map_.find(a);
              while (v == nullptr) {
                a = parentKey(a);
                v = map_.find(a);
              }
              if (*v == kInternal) break;
              ++stats_.balanceSplits;
              splitLeafOnce(*v, labeller);
            }
          }
        }
        internal.swap(nodes);
      }
      // Complex (or geometrically rough) leaves created by balancing get refined; their
      // children are deeper than the pass has looked, so only they call for another pass
      // (a balancing split makes nodes at depths the pass has yet to visit).
      std::vector<std::int32_t> wanting;
      wanting.swap(wantSplit_);
      for (const std::int32_t i : wanting)
        if (alive_[static_cast<std::size_t>(i)]) {
          splitLeaf(i, labeller);
          changed = true;
        }
    }
  }

  /// Splits a leaf into 8 child leaves (no recursion: balance keeps its own order).
  void splitLeafOnce(std::int32_t index, FaceLabeller& labeller) {
    const MortonKey key = records_[static_cast<std::size_t>(index)].key;
    alive_[static_cast<std::size_t>(index)] = false;
    markInternal(key);
    for (int o = 0; o < 8; ++o) {
      const Evaluation ev = evaluateOnce(childKey(key, o), labeller);
      count(ev);
      addLeaf(ev);  // a child that wants a split is refined by the pass after the ripple
    }
  }

  /// The leaves in Z order (a pre-order walk down the internal nodes, children in
  /// octant order), so LinearOctree need not sort them.
  LinearOctree finish(OctreeBuildStats* stats) {
    std::vector<OctreeLeaf> leaves;
    leaves.reserve(records_.size());
    std::vector<MortonKey> stack{kRootKey};
    while (!stack.empty()) {
      const MortonKey key = stack.back();
      stack.pop_back();
      const std::int32_t* v = map_.find(key);
      if (*v == kInternal) {
        for (int o = 7; o >= 0; --o) stack.push_back(childKey(key, o));
        continue;
      }
      const OctreeLeaf& leaf = records_[static_cast<std::size_t>(*v)];
      leaves.push_back(leaf);
      stats_.unresolvedComplexLeaves += leaf.complex;
    }
    if (stats) *stats = stats_;
    return LinearOctree(samples_.size, samples_.origin, std::move(leaves));
  }

 private:
  /// Adaptive mode in the voxel reading (ContourSettings::adaptiveReadsVoxels): every node
  /// above the unit cells that holds a unit cell within one cell of one the two readings can differ on
  /// (cell::voxelReadingDiffers), by depth, (S >> (maxDepth - depth))^3 flags in x-fastest
  /// order. Those cells and their neighbours stay unit leaves, so that every edge of such a
  /// cell lies between four unit leaves, where the voxel reading's polygons are made.
  void markVoxelReadingCells() {
    const int maxDepth = depths_.maxDepth, size = samples_.size;
    voxelSplits_.resize(static_cast<std::size_t>(maxDepth));
    for (int d = 0; d < maxDepth; ++d) {
      const auto n = static_cast<std::size_t>(size >> (maxDepth - d));
      voxelSplits_[static_cast<std::size_t>(d)].assign(n * n * n, false);
    }
    // Cells from one before the meta-cell to one after it: a cell of the next meta-cell
    // keeps this one's cells beside it at one voxel too (the samples' apron holds them).
    forEachCrossedUnitCell(phases_, {-1, -1, -1}, size + 2, [&](const std::array<int, 3>& cell, std::uint8_t config) {
      if (!cell::voxelReadingDiffers(config)) return;
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const std::array<int, 3> p{cell[0] + dx, cell[1] + dy, cell[2] + dz};
            if (std::min({p[0], p[1], p[2]}) < 0 || std::max({p[0], p[1], p[2]}) >= size) continue;
            for (int d = maxDepth - 1; d >= 0; --d) {  // the ancestors, until one is marked
              const int shift = maxDepth - d, n = size >> shift;
              const auto index =
                  static_cast<std::size_t>(((p[2] >> shift) * n + (p[1] >> shift)) * n + (p[0] >> shift));
              auto& flags = voxelSplits_[static_cast<std::size_t>(d)];
              if (flags[index]) break;
              flags[index] = true;
            }
          }
    });
  }

  bool voxelSplit(const KeyCoord& c) const noexcept {
    const auto& flags = voxelSplits_[static_cast<std::size_t>(c.depth)];
    const int n = samples_.size >> (depths_.maxDepth - c.depth);
    return flags[static_cast<std::size_t>((c.xyz[2] * n + c.xyz[1]) * n + c.xyz[0])];
  }

  void markInternal(MortonKey key) {
    map_.assign(key, kInternal);
    internal_.mark(key);
  }

  void addLeaf(const Evaluation& ev) {
    const auto index = static_cast<std::int32_t>(records_.size());
    records_.push_back(ev.leaf);
    alive_.push_back(true);
    leavesAtDepth_[ev.leaf.depth].push_back({ev.leaf.key, index});
    if (ev.split) wantSplit_.push_back(index);
    map_.assign(ev.leaf.key, index);
  }

  const cell::MetaCellSamples& samples_;
  const cell::ContourSettings& settings_;
  const OctreeOptions& options_;
  OctreeDepths depths_;
  const UnitEdgeCrossings* crossings_;     // optional: what the dual vertices read
  std::optional<SamplePhases> ownPhases_;  // where the caller gave none
  const SamplePhases& phases_;             // what the criteria read
  BuildMemo::Impl* memo_;                  // optional: earlier builds' evaluations
  CellClassifyOptions classify_;
  OctreeBuildStats stats_;
  std::vector<OctreeLeaf> records_;  // every leaf made, split ones too (alive_)
  std::vector<bool> alive_;
  /// A leaf as balancing reads it: a record's key beside its index (reading the keys out of
  /// the 48-byte records missed the cache: a tenth of balancing's own time).
  struct DepthLeaf {
    MortonKey key;
    std::int32_t index;
  };
  std::vector<std::vector<DepthLeaf>> leavesAtDepth_;  // dead ones too, per depth
  std::vector<std::int32_t> wantSplit_;                // records that want a split (made by balancing), in order
  std::vector<std::vector<bool>> voxelSplits_;         // markVoxelReadingCells (empty: not that reading)
  KeyMap map_;
  InternalNodeBits internal_;
};

int checkedDepth(int metaCellSize, int cellSize, const char* field) {
  if (cellSize < 1 || cellSize > metaCellSize || (cellSize & (cellSize - 1)) != 0)
    throw InputError(std::string("octree options: ") + field + ": expected a power of two in [1, " +
                     std::to_string(metaCellSize) + "], got " + std::to_string(cellSize));
  return depthForCellSize(metaCellSize, cellSize);
}

}  // namespace

int finestLeafSize(const OctreeOptions& options, int metaCellSize) {
  return cellSizeAtDepth(metaCellSize, resolveDepths(options, metaCellSize).maxDepth);
}

OctreeDepths resolveDepths(const OctreeOptions& options, int metaCellSize) {
  if (metaCellSize < 1 || (metaCellSize & (metaCellSize - 1)) != 0)
    throw InputError("octree: meta-cell size: expected a power of two, got " + std::to_string(metaCellSize));
  const int finest = depthForCellSize(metaCellSize, 1);
  if (finest > kMaxKeyDepth) throw InputError("octree: meta-cell size too large for 64-bit Morton keys");
  OctreeDepths d;
  // A depth given (>= 0) wins over the cell size; the size then over the default.
  d.maxDepth = options.maxDepth >= 0        ? options.maxDepth
               : options.finestCellSize > 0 ? checkedDepth(metaCellSize, options.finestCellSize, "finestCellSize")
                                            : finest;
  d.minDepth = options.minDepth >= 0 ? options.minDepth
               : options.maxCellSize > 0
                   ? checkedDepth(metaCellSize, std::min(options.maxCellSize, metaCellSize), "maxCellSize")
                   : 0;
  if (d.maxDepth > finest)
    throw InputError("octree options: maxDepth: expected at most " + std::to_string(finest) + " (1-voxel cells), got " +
                     std::to_string(d.maxDepth));
  if (d.minDepth < 0 || d.minDepth > d.maxDepth)
    throw InputError("octree options: minDepth: expected in [0, maxDepth = " + std::to_string(d.maxDepth) + "], got " +
                     std::to_string(d.minDepth));
  return d;
}

OctreeBuildStats& OctreeBuildStats::operator+=(const OctreeBuildStats& o) {
  if (cellsClassified.size() < o.cellsClassified.size()) cellsClassified.resize(o.cellsClassified.size(), 0);
  for (std::size_t d = 0; d < o.cellsClassified.size(); ++d) cellsClassified[d] += o.cellsClassified[d];
  complexEdges += o.complexEdges;
  complexFaces += o.complexFaces;
  interiorComponents += o.interiorComponents;
  complexCells += o.complexCells;
  unresolvedComplexLeaves += o.unresolvedComplexLeaves;
  geometricSplits += o.geometricSplits;
  featureSplits += o.featureSplits;
  errorBoundSplits += o.errorBoundSplits;
  dataBoxSplits += o.dataBoxSplits;
  multiSheetSplits += o.multiSheetSplits;
  hiddenComponentSplits += o.hiddenComponentSplits;
  balanceSplits += o.balanceSplits;
  return *this;
}

LinearOctree buildOctree(const cell::MetaCellSamples& samples, const cell::ContourSettings& settings,
                         const OctreeOptions& options, OctreeBuildStats* stats, Interrupter* interrupter,
                         const UnitEdgeCrossings* crossings, const SamplePhases* phases, BuildMemo* memo) {
  if (settings.method == cell::ContourMethod::Vdb)
    throw InputError("octree: the vdb method builds no octree (regular or adaptive)");
  const OctreeDepths depths = resolveDepths(options, samples.size);
  Builder builder(samples, settings, options, depths, crossings, phases, memo);
  builder.buildTopDown(interrupter);
  if (settings.method == cell::ContourMethod::Adaptive) builder.balance(interrupter);
  return builder.finish(stats);
}

bool isBalanced(const LinearOctree& octree) {
  for (const OctreeLeaf& l : octree.leaves()) {
    if (l.depth < 2) continue;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const MortonKey n = neighbourKey(l.key, dx, dy, dz);
          if (n == kInvalidKey || n == l.key) continue;
          const std::int64_t j = octree.findLeafContaining(n);
          if (j != LinearOctree::kNone && octree.leaf(static_cast<std::size_t>(j)).depth + 1 < l.depth) return false;
        }
  }
  return true;
}

}  // namespace isovdb::octree
