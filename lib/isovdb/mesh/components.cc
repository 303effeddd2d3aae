// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/components.h"

#include <algorithm>
#include <atomic>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace isovdb::mesh {

namespace {

using Range = tbb::blocked_range<std::size_t>;
constexpr std::size_t kGrain = 1 << 13;
constexpr std::uint32_t kNone = 0xffffffffu;

/// Concurrent union-find over vertices: a root is always the smallest index
/// of its set (larger roots are linked under smaller ones), so the final
/// partition and its roots do not depend on the schedule.
class ConcurrentUnionFind {
 public:
  explicit ConcurrentUnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }

  std::uint32_t find(std::uint32_t x) {
    while (true) {
      std::uint32_t p = load(x);
      if (p == x) return x;
      const std::uint32_t g = load(p);
      if (g == p) return p;
      std::atomic_ref<std::uint32_t>(parent_[x]).compare_exchange_weak(p, g, std::memory_order_relaxed);
      x = g;
    }
  }

  void unite(std::uint32_t a, std::uint32_t b) {
    while (true) {
      a = find(a);
      b = find(b);
      if (a == b) return;
      if (a < b) std::swap(a, b);
      std::uint32_t expected = a;
      if (std::atomic_ref<std::uint32_t>(parent_[a]).compare_exchange_strong(expected, b, std::memory_order_relaxed))
        return;
    }
  }

 private:
  std::uint32_t load(std::uint32_t x) {
    return std::atomic_ref<std::uint32_t>(parent_[x]).load(std::memory_order_relaxed);
  }
  std::vector<std::uint32_t> parent_;
};

}  // namespace

std::vector<std::uint32_t> vertexComponentRoots(const Mesh& mesh, const std::function<bool(std::size_t)>& joins) {
  const std::size_t n = mesh.positions.size();
  ConcurrentUnionFind sets(n);
  tbb::parallel_for(Range(0, mesh.triangles.size(), kGrain), [&](const Range& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      if (joins && !joins(t)) continue;
      const Triangle& tri = mesh.triangles[t];
      sets.unite(tri[0], tri[1]);
      sets.unite(tri[0], tri[2]);
    }
  });
  std::vector<std::uint32_t> root(n);
  tbb::parallel_for(Range(0, n, kGrain), [&](const Range& r) {
    for (std::size_t v = r.begin(); v != r.end(); ++v) root[v] = sets.find(static_cast<std::uint32_t>(v));
  });
  return root;
}

std::vector<Mesh> splitComponents(const Mesh& mesh) {
  const std::vector<std::uint32_t> root = vertexComponentRoots(mesh);
  std::vector<std::uint32_t> label(mesh.positions.size(), kNone);  // indexed by root
  std::vector<Mesh> parts;
  std::vector<std::uint32_t> triangleLabel(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::uint32_t& l = label[root[mesh.triangles[t][0]]];
    if (l == kNone) {
      l = static_cast<std::uint32_t>(parts.size());
      parts.emplace_back();
    }
    triangleLabel[t] = l;
  }
  // Vertices in their order: the new index of each used vertex within its part. A vertex
  // no triangle uses is a set of its own, so its root got no label.
  std::vector<std::uint32_t> local(mesh.positions.size(), kNone);
  const bool normals = mesh.normals.size() == mesh.positions.size() && !mesh.normals.empty();
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    if (label[root[v]] == kNone) continue;
    Mesh& part = parts[label[root[v]]];
    local[v] = static_cast<std::uint32_t>(part.positions.size());
    part.positions.push_back(mesh.positions[v]);
    if (normals) part.normals.push_back(mesh.normals[v]);
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    parts[triangleLabel[t]].triangles.push_back({local[tri[0]], local[tri[1]], local[tri[2]]});
  }
  return parts;
}

}  // namespace isovdb::mesh
