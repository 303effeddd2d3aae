// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/self_intersection.h"

#include "isovdb/bit_interleave.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include "isovdb/errors.h"
#include "isovdb/mesh/mesh_checks.h"

namespace isovdb::mesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle3 = Kernel::Triangle_3;
using Pair = std::pair<std::uint32_t, std::uint32_t>;

constexpr std::uint32_t kLeafSize = 16;         ///< triangles per BVH leaf, at most
constexpr std::uint32_t kParallelItems = 8192;  ///< subtrees larger than this split into tasks
constexpr std::uint32_t kNone = 0xffffffffu;

/// Axis-aligned box; float bounds are exact because positions are floats.
struct Box {
  std::array<float, 3> lo{}, hi{};

  void extend(const Box& b) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], b.lo[k]);
      hi[k] = std::max(hi[k], b.hi[k]);
    }
  }
  float halfPerimeter() const { return (hi[0] - lo[0]) + (hi[1] - lo[1]) + (hi[2] - lo[2]); }
};

/// Closed boxes: touching counts, since touching triangles intersect.
bool overlaps(const Box& a, const Box& b) {
  return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] && a.lo[2] <= b.hi[2] &&
         b.lo[2] <= a.hi[2];
}

Box boxOf(const Vec3f& a, const Vec3f& b) {
  Box box;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = std::min(a[k], b[k]);
    box.hi[k] = std::max(a[k], b[k]);
  }
  return box;
}

Box boxOf(const Vec3f& a, const Vec3f& b, const Vec3f& c) {
  Box box = boxOf(a, b);
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = std::min(box.lo[k], c[k]);
    box.hi[k] = std::max(box.hi[k], c[k]);
  }
  return box;
}

Point toPoint(const Vec3f& p) { return Point(double(p[0]), double(p[1]), double(p[2])); }

/// A repeated index, or three collinear points: skipped (validateMesh counts them).
bool degenerateTriangle(const Mesh& mesh, const Triangle& t) {
  return t[0] == t[1] || t[1] == t[2] || t[0] == t[2] ||
         CGAL::collinear(toPoint(mesh.positions[t[0]]), toPoint(mesh.positions[t[1]]), toPoint(mesh.positions[t[2]]));
}

struct Item {
  Box box;
  std::uint32_t triangle = 0;
  std::uint32_t copies = 1;  ///< triangles with this one's three indices (it stands for them all)
};

/// Triangles with the same three vertex indices meet every other triangle alike (the
/// narrow phase reads indices and positions only), so each set is tested once: a mesh
/// of many copies of one triangle costs time in its size, not its square.
struct CopySets {
  /// Every set of two or more, lowest triangle first, by that triangle.
  std::map<std::uint32_t, std::vector<std::uint32_t>> sets;
  /// Pairs inside the sets: each intersects (same indices, see the header).
  std::int64_t pairsWithin = 0;

  const std::vector<std::uint32_t>* find(std::uint32_t triangle) const {
    const auto it = sets.find(triangle);
    return it == sets.end() ? nullptr : &it->second;
  }
};

/// BVH node. The left child of an inner node directly follows it.
struct Node {
  Box box;
  std::uint32_t begin = 0;  ///< first item of the subtree
  std::uint32_t count = 0;  ///< items in the subtree; a leaf when count <= kLeafSize
  std::uint32_t right = kNone;

  bool leaf() const { return count <= kLeafSize; }
};

/// Nodes of the subtree over `n` items (the split is always n/2 | n - n/2,
/// so the layout is fixed by n and the build can place subtrees in parallel).
class NodeCounts {
 public:
  explicit NodeCounts(std::size_t n) { compute(n); }
  std::size_t operator()(std::size_t n) const { return n <= kLeafSize ? 1 : counts_.at(n); }

 private:
  std::size_t compute(std::size_t n) {
    if (n <= kLeafSize) return 1;
    if (auto it = counts_.find(n); it != counts_.end()) return it->second;
    const std::size_t c = 1 + compute(n / 2) + compute(n - n / 2);
    counts_.emplace(n, c);
    return c;
  }
  std::map<std::size_t, std::size_t> counts_;
};

/// Bounding-volume hierarchy over items sorted along a Morton curve
/// (collectItems()): every inner node splits its range in halves, and boxes
/// are merged bottom-up.
class Bvh {
 public:
  explicit Bvh(std::vector<Item> items) : items_(std::move(items)) {
    if (items_.empty()) return;
    const NodeCounts counts(items_.size());
    nodes_.resize(counts(items_.size()));
    build(counts, 0, 0, static_cast<std::uint32_t>(items_.size()));
  }

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<Item>& items() const { return items_; }

 private:
  void build(const NodeCounts& counts, std::uint32_t index, std::uint32_t begin, std::uint32_t end) {
    Node& node = nodes_[index];
    node.begin = begin;
    node.count = end - begin;
    if (node.leaf()) {
      node.box = items_[begin].box;
      for (std::uint32_t i = begin + 1; i < end; ++i) node.box.extend(items_[i].box);
      return;
    }
    const std::uint32_t mid = begin + node.count / 2;
    const std::uint32_t left = index + 1;
    const auto right = static_cast<std::uint32_t>(left + counts(mid - begin));
    node.right = right;
    if (node.count > kParallelItems)
      tbb::parallel_invoke([&] { build(counts, left, begin, mid); }, [&] { build(counts, right, mid, end); });
    else {
      build(counts, left, begin, mid);
      build(counts, right, mid, end);
    }
    node.box = nodes_[left].box;
    node.box.extend(nodes_[right].box);
  }

  std::vector<Item> items_;
  std::vector<Node> nodes_;
};

/// The exact narrow phase for two non-degenerate triangles (see the header).
class PairTest {
 public:
  explicit PairTest(const Mesh& mesh) : mesh_(mesh) {}

  bool intersect(std::uint32_t ta, std::uint32_t tb) const {
    return intersect(mesh_.triangles[ta], mesh_.triangles[tb]);
  }

  bool intersect(const Triangle& a, const Triangle& b) const {
    int sharedA[3], sharedB[3], shared = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (a[i] == b[j]) {
          sharedA[shared] = i;
          sharedB[shared] = j;
          ++shared;
        }
    const auto& pos = mesh_.positions;
    if (shared >= 2) {
      // Shared edge (p, q) with opposite vertices r (in a) and s (in b).
      const Point p = toPoint(pos[a[sharedA[0]]]);
      const Point q = toPoint(pos[a[sharedA[1]]]);
      const Point r = toPoint(pos[a[3 - sharedA[0] - sharedA[1]]]);
      const Point s = toPoint(pos[b[3 - sharedB[0] - sharedB[1]]]);
      return CGAL::coplanar(p, q, r, s) && CGAL::coplanar_orientation(p, q, r, s) == CGAL::POSITIVE;
    }
    if (shared == 1) {
      const int i = sharedA[0], j = sharedB[0];
      return edgeMeetsTriangle(b[(j + 1) % 3], b[(j + 2) % 3], a) ||
             edgeMeetsTriangle(a[(i + 1) % 3], a[(i + 2) % 3], b);
    }
    return CGAL::do_intersect(triangle(a), triangle(b));
  }

 private:
  Triangle3 triangle(const Triangle& t) const {
    return Triangle3(toPoint(mesh_.positions[t[0]]), toPoint(mesh_.positions[t[1]]), toPoint(mesh_.positions[t[2]]));
  }

  bool edgeMeetsTriangle(std::uint32_t v0, std::uint32_t v1, const Triangle& t) const {
    const auto& pos = mesh_.positions;
    if (!overlaps(boxOf(pos[v0], pos[v1]), boxOf(pos[t[0]], pos[t[1]], pos[t[2]]))) return false;
    return CGAL::do_intersect(triangle(t), Segment(toPoint(pos[v0]), toPoint(pos[v1])));
  }

  const Mesh& mesh_;
};

/// Dual traversal of the BVH against itself: every unordered pair of items is
/// reached exactly once, at the node where the two separate.
class Collider {
 public:
  Collider(const Bvh& bvh, const PairTest& test, const CopySets& copies, bool keepPairs)
      : nodes_(bvh.nodes()), items_(bvh.items()), test_(test), copies_(copies), keepPairs_(keepPairs) {}

  void run() {
    if (!nodes_.empty()) self(0);
  }

  std::int64_t count() { return count_.combine(std::plus<>()); }

  std::vector<Pair> pairs() {
    std::vector<Pair> all;
    for (auto& local : pairs_) all.insert(all.end(), local.begin(), local.end());
    tbb::parallel_sort(all.begin(), all.end());
    return all;
  }

 private:
  void self(std::uint32_t index) {
    const Node& node = nodes_[index];
    if (node.leaf()) {
      for (std::uint32_t i = node.begin; i < node.begin + node.count; ++i)
        for (std::uint32_t j = i + 1; j < node.begin + node.count; ++j) testItems(i, j);
      return;
    }
    const std::uint32_t left = index + 1, right = node.right;
    if (node.count > kParallelItems)
      tbb::parallel_invoke([&] { self(left); }, [&] { self(right); }, [&] { cross(left, right); });
    else {
      self(left);
      self(right);
      cross(left, right);
    }
  }

  void cross(std::uint32_t ia, std::uint32_t ib) {
    const Node& a = nodes_[ia];
    const Node& b = nodes_[ib];
    if (!overlaps(a.box, b.box)) return;
    if (a.leaf() && b.leaf()) {
      // Only items that reach into the other leaf's box can meet its items.
      std::uint32_t nearA[kLeafSize], nearB[kLeafSize], countA = 0, countB = 0;
      for (std::uint32_t i = a.begin; i < a.begin + a.count; ++i)
        if (overlaps(items_[i].box, b.box)) nearA[countA++] = i;
      if (countA == 0) return;
      for (std::uint32_t j = b.begin; j < b.begin + b.count; ++j)
        if (overlaps(items_[j].box, a.box)) nearB[countB++] = j;
      for (std::uint32_t i = 0; i < countA; ++i)
        for (std::uint32_t j = 0; j < countB; ++j) testItems(nearA[i], nearB[j]);
      return;
    }
    const bool splitA = b.leaf() || (!a.leaf() && a.box.halfPerimeter() >= b.box.halfPerimeter());
    const std::uint32_t split = splitA ? ia : ib, other = splitA ? ib : ia;
    const std::uint32_t c0 = split + 1, c1 = nodes_[split].right;
    if (a.count + b.count > kParallelItems)
      tbb::parallel_invoke([&] { cross(c0, other); }, [&] { cross(c1, other); });
    else {
      cross(c0, other);
      cross(c1, other);
    }
  }

  void testItems(std::uint32_t i, std::uint32_t j) {
    const Item& a = items_[i];
    const Item& b = items_[j];
    if (!overlaps(a.box, b.box) || !test_.intersect(a.triangle, b.triangle)) return;
    count_.local() += std::int64_t{a.copies} * b.copies;
    if (!keepPairs_) return;
    const std::uint32_t aloneA[1] = {a.triangle}, aloneB[1] = {b.triangle};
    const std::vector<std::uint32_t>* setA = a.copies > 1 ? copies_.find(a.triangle) : nullptr;
    const std::vector<std::uint32_t>* setB = b.copies > 1 ? copies_.find(b.triangle) : nullptr;
    const std::span<const std::uint32_t> sa = setA ? std::span<const std::uint32_t>(*setA) : aloneA;
    const std::span<const std::uint32_t> sb = setB ? std::span<const std::uint32_t>(*setB) : aloneB;
    for (const std::uint32_t x : sa)
      for (const std::uint32_t y : sb) pairs_.local().emplace_back(std::min(x, y), std::max(x, y));
  }

  const std::vector<Node>& nodes_;
  const std::vector<Item>& items_;
  const PairTest& test_;
  const CopySets& copies_;
  const bool keepPairs_;
  tbb::combinable<std::int64_t> count_{[] { return std::int64_t{0}; }};
  tbb::enumerable_thread_specific<std::vector<Pair>> pairs_;
};

/// Boxes of the non-degenerate triangles, sorted along a Morton (Z-order)
/// curve of the box centres (ties by triangle index), so that items close in
/// the array are close in space.
/// @throw InputError for a missing vertex or a non-finite coordinate (the
///        lowest offending triangle is named, whatever the thread count).
std::vector<Item> collectItems(const Mesh& mesh, CopySets& copies) {
  const std::size_t n = mesh.triangles.size();
  constexpr std::uint64_t kSkipped = ~std::uint64_t{0};  // above every 63-bit Morton code
  struct Key {
    std::uint64_t code;
    std::uint32_t triangle;
    bool operator<(const Key& o) const { return code < o.code || (code == o.code && triangle < o.triangle); }
  };
  struct Bounds {
    std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    std::size_t kept = 0;
  };
  auto boxOfTriangle = [&](std::size_t t) {
    const Triangle& tri = mesh.triangles[t];
    return boxOf(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]);
  };
  auto centre = [](const Box& box, int k) { return 0.5 * (double(box.lo[k]) + double(box.hi[k])); };

  // Pass 1: validity, degeneracy and the bounds of the kept boxes' centres.
  std::vector<Key> keys(n);
  std::atomic<std::size_t> firstBad{n};
  const Bounds bounds = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, 1 << 13), Bounds{},
      [&](const tbb::blocked_range<std::size_t>& r, Bounds b) {
        for (std::size_t t = r.begin(); t != r.end(); ++t) {
          keys[t] = {kSkipped, static_cast<std::uint32_t>(t)};
          const Triangle& tri = mesh.triangles[t];
          if (detail::invalidTriangle(mesh, tri)) {
            detail::keepLowest(firstBad, t);
            continue;
          }
          if (degenerateTriangle(mesh, tri)) continue;
          keys[t].code = 0;
          ++b.kept;
          const Box box = boxOfTriangle(t);
          for (int k = 0; k < 3; ++k) {
            b.lo[k] = std::min(b.lo[k], centre(box, k));
            b.hi[k] = std::max(b.hi[k], centre(box, k));
          }
        }
        return b;
      },
      [](Bounds a, const Bounds& b) {
        for (int k = 0; k < 3; ++k) {
          a.lo[k] = std::min(a.lo[k], b.lo[k]);
          a.hi[k] = std::max(a.hi[k], b.hi[k]);
        }
        a.kept += b.kept;
        return a;
      });
  if (const std::size_t t = firstBad.load(); t < n) detail::throwInvalidTriangle(mesh, t, "countSelfIntersections");

  // Sets of kept triangles with the same indices: the lowest stays, the others are skipped.
  std::vector<std::uint32_t> copyCount(n, 1);
  {
    struct Indices {
      std::array<std::uint32_t, 3> sorted;
      std::uint32_t triangle;
      bool operator<(const Indices& o) const {
        return sorted < o.sorted || (sorted == o.sorted && triangle < o.triangle);
      }
    };
    std::vector<Indices> byIndices;
    byIndices.reserve(bounds.kept);
    for (std::size_t t = 0; t < n; ++t) {
      if (keys[t].code == kSkipped) continue;
      std::array<std::uint32_t, 3> s = mesh.triangles[t];
      std::sort(s.begin(), s.end());
      byIndices.push_back({s, static_cast<std::uint32_t>(t)});
    }
    tbb::parallel_sort(byIndices.begin(), byIndices.end());
    for (std::size_t i = 0; i < byIndices.size();) {
      std::size_t j = i + 1;
      while (j < byIndices.size() && byIndices[j].sorted == byIndices[i].sorted) ++j;
      if (j - i > 1) {
        const std::uint32_t first = byIndices[i].triangle;
        std::vector<std::uint32_t>& set = copies.sets[first];
        for (std::size_t k = i; k < j; ++k) {
          set.push_back(byIndices[k].triangle);
          if (k > i) keys[byIndices[k].triangle].code = kSkipped;
        }
        const auto k = static_cast<std::int64_t>(j - i);
        copyCount[first] = static_cast<std::uint32_t>(k);
        copies.pairsWithin += k * (k - 1) / 2;
      }
      i = j;
    }
  }
  std::size_t kept = 0;
  for (std::size_t t = 0; t < n; ++t) kept += keys[t].code != kSkipped;

  // Pass 2: Morton codes on a 2^21 lattice per axis, then one parallel sort.
  std::array<double, 3> scale{};
  for (int k = 0; k < 3; ++k) {
    const double extent = bounds.hi[k] - bounds.lo[k];
    scale[k] = extent > 0 ? double((1 << 21) - 1) / extent : 0.0;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1 << 13), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      if (keys[t].code == kSkipped) continue;
      const Box box = boxOfTriangle(t);
      std::uint64_t code = 0;
      for (int k = 0; k < 3; ++k)
        code |= spreadBits3(static_cast<std::uint64_t>((centre(box, k) - bounds.lo[k]) * scale[k])) << k;
      keys[t].code = code;
    }
  });
  tbb::parallel_sort(keys.begin(), keys.end());

  std::vector<Item> items(kept);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, items.size(), 1 << 13),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        items[i] = {boxOfTriangle(keys[i].triangle), keys[i].triangle, copyCount[keys[i].triangle]};
                    });
  return items;
}

}  // namespace

bool trianglesIntersect(const Mesh& mesh, const Triangle& a, const Triangle& b) {
  const auto& p = mesh.positions;  // the boxes first: they settle most pairs, the exact tests few
  if (!overlaps(boxOf(p[a[0]], p[a[1]], p[a[2]]), boxOf(p[b[0]], p[b[1]], p[b[2]]))) return false;
  if (degenerateTriangle(mesh, a) || degenerateTriangle(mesh, b)) return false;
  return PairTest(mesh).intersect(a, b);
}

std::int64_t countSelfIntersections(const Mesh& mesh, std::vector<Pair>* pairs) {
  if (mesh.triangles.size() >= kNone)
    throw InputError("countSelfIntersections: the mesh has " + std::to_string(mesh.triangles.size()) +
                     " triangles; at most 2^32 - 2 are supported");
  if (pairs) pairs->clear();
  CopySets copies;
  const Bvh bvh(collectItems(mesh, copies));
  const PairTest test(mesh);
  Collider collider(bvh, test, copies, pairs != nullptr);
  collider.run();
  if (pairs) {
    *pairs = collider.pairs();
    for (const auto& [first, set] : copies.sets)
      for (std::size_t i = 0; i < set.size(); ++i)
        for (std::size_t j = i + 1; j < set.size(); ++j) pairs->emplace_back(set[i], set[j]);
    tbb::parallel_sort(pairs->begin(), pairs->end());
  }
  return collider.count() + copies.pairsWithin;
}

}  // namespace isovdb::mesh
