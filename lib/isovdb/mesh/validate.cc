// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/validate.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <functional>
#include <cmath>
#include <numeric>
#include <string>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "isovdb/errors.h"
#include "isovdb/mesh/components.h"
#include "isovdb/mesh/measures.h"
#include "isovdb/mesh/mesh_checks.h"
#include "isovdb/mesh/self_intersection.h"
#include "isovdb/union_find.h"

namespace isovdb::mesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Range = tbb::blocked_range<std::size_t>;

constexpr std::size_t kGrain = 1 << 13;
constexpr std::uint32_t kNone = 0xffffffffu;

Point toPoint(const Vec3f& p) { return Point(double(p[0]), double(p[1]), double(p[2])); }

bool collapsed(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }

enum TriangleFlag : std::uint8_t { kProper = 0, kCollapsed = 1, kFlat = 2 };

/// Per-triangle classification; throws for the lowest invalid triangle.
std::vector<std::uint8_t> classifyTriangles(const Mesh& mesh) {
  const std::size_t n = mesh.triangles.size();
  std::vector<std::uint8_t> flags(n, kProper);
  std::atomic<std::size_t> firstBad{n};
  tbb::parallel_for(Range(0, n, kGrain), [&](const Range& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      const Triangle& tri = mesh.triangles[t];
      if (detail::invalidTriangle(mesh, tri)) {
        detail::keepLowest(firstBad, t);
      } else if (collapsed(tri)) {
        flags[t] = kCollapsed;
      } else if (CGAL::collinear(toPoint(mesh.positions[tri[0]]), toPoint(mesh.positions[tri[1]]),
                                 toPoint(mesh.positions[tri[2]]))) {
        flags[t] = kFlat;
      }
    }
  });
  if (const std::size_t t = firstBad.load(); t < n) detail::throwInvalidTriangle(mesh, t, "validateMesh");
  return flags;
}

/// For each vertex, the other two corners of its incident proper triangles,
/// in the triangle's winding order: (next, previous). CSR layout.
struct Stars {
  std::vector<std::size_t> offsets;  ///< vertexCount + 1
  std::vector<std::array<std::uint32_t, 2>> corners;
};

Stars buildStars(const Mesh& mesh, const std::vector<std::uint8_t>& flags) {
  const std::size_t n = mesh.positions.size();
  const std::size_t triangleCount = mesh.triangles.size();
  Stars stars;
  std::vector<std::uint32_t> degree(n, 0);
  tbb::parallel_for(Range(0, triangleCount, kGrain), [&](const Range& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t)
      if (flags[t] != kCollapsed)
        for (const std::uint32_t v : mesh.triangles[t])
          std::atomic_ref<std::uint32_t>(degree[v]).fetch_add(1, std::memory_order_relaxed);
  });
  stars.offsets.resize(n + 1);
  stars.offsets[0] = 0;
  std::inclusive_scan(degree.begin(), degree.end(), stars.offsets.begin() + 1, std::plus<>(), std::size_t{0});
  // `degree` becomes the fill cursor: the next free slot, counted from the end.
  stars.corners.resize(stars.offsets[n]);
  tbb::parallel_for(Range(0, triangleCount, kGrain), [&](const Range& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      if (flags[t] == kCollapsed) continue;
      const Triangle& tri = mesh.triangles[t];
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = tri[k];
        const std::uint32_t left = std::atomic_ref<std::uint32_t>(degree[v]).fetch_sub(1, std::memory_order_relaxed);
        stars.corners[stars.offsets[v] + left - 1] = {tri[(k + 1) % 3], tri[(k + 2) % 3]};
      }
    }
  });
  return stars;
}

/// What the umbrella of one vertex says about it and about the edges it owns
/// (an edge {v, w} is owned by v when v < w).
struct VertexFigures {
  std::uint32_t ownedEdges = 0;
  std::uint8_t flags = 0;
};
enum VertexFlag : std::uint8_t { kReferenced = 1, kBoundaryEdge = 2, kNonManifoldEdge = 4, kNonManifoldVertex = 8 };

struct Totals {
  std::int64_t edges = 0, boundaryEdges = 0, nonManifoldEdges = 0, nonManifoldVertices = 0, inconsistentEdges = 0,
               referencedVertices = 0;
  Totals& operator+=(const Totals& o) {
    edges += o.edges;
    boundaryEdges += o.boundaryEdges;
    nonManifoldEdges += o.nonManifoldEdges;
    nonManifoldVertices += o.nonManifoldVertices;
    inconsistentEdges += o.inconsistentEdges;
    referencedVertices += o.referencedVertices;
    return *this;
  }
};

Totals analyseUmbrellas(const Stars& stars, std::vector<VertexFigures>& figures) {
  const std::size_t n = figures.size();
  tbb::combinable<Totals> totals;
  tbb::parallel_for(Range(0, n, kGrain / 4), [&](const Range& r) {
    struct Entry {
      std::uint32_t other;
      std::uint32_t triangle;  ///< position in the umbrella
      bool outgoing;           ///< the triangle runs v -> other
    };
    std::vector<Entry> entries;
    std::vector<std::uint32_t> parent;
    Totals& local = totals.local();
    for (std::size_t v = r.begin(); v != r.end(); ++v) {
      const std::size_t begin = stars.offsets[v];
      const auto degree = static_cast<std::uint32_t>(stars.offsets[v + 1] - begin);
      if (degree == 0) continue;
      entries.clear();
      parent.resize(degree);
      for (std::uint32_t k = 0; k < degree; ++k) {
        const auto& [next, previous] = stars.corners[begin + k];
        entries.push_back({next, k, true});
        entries.push_back({previous, k, false});
        parent[k] = k;
      }
      std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.other < b.other; });
      VertexFigures fig;
      fig.flags = kReferenced;
      std::uint32_t fans = degree;
      for (std::size_t g = 0; g < entries.size();) {
        std::size_t e = g + 1;
        while (e < entries.size() && entries[e].other == entries[g].other) ++e;
        for (std::size_t i = g + 1; i < e; ++i) {
          const std::uint32_t a = findRoot(parent, entries[g].triangle);
          const std::uint32_t b = findRoot(parent, entries[i].triangle);
          if (a != b) {
            parent[std::max(a, b)] = std::min(a, b);
            --fans;
          }
        }
        if (v < entries[g].other) {
          const std::size_t m = e - g;  // triangles on edge {v, other}
          ++fig.ownedEdges;
          if (m == 1) {
            ++local.boundaryEdges;
            fig.flags |= kBoundaryEdge;
          } else if (m > 2) {
            ++local.nonManifoldEdges;
            fig.flags |= kNonManifoldEdge;
          } else if (entries[g].outgoing == entries[g + 1].outgoing) {
            ++local.inconsistentEdges;
          }
        }
        g = e;
      }
      if (fans > 1) {
        fig.flags |= kNonManifoldVertex;
        ++local.nonManifoldVertices;
      }
      local.edges += fig.ownedEdges;
      ++local.referencedVertices;
      figures[v] = fig;
    }
  });
  return totals.combine([](Totals a, const Totals& b) { return a += b; });
}

/// Component labels in the order of each component's first triangle; fills
/// the per-component figures from the per-vertex ones.
std::vector<ComponentReport> buildComponents(const Mesh& mesh, const std::vector<std::uint8_t>& flags,
                                             const std::vector<VertexFigures>& figures) {
  const std::size_t n = mesh.positions.size();
  const std::size_t triangleCount = mesh.triangles.size();
  const std::vector<std::uint32_t> root =
      vertexComponentRoots(mesh, [&](std::size_t t) { return flags[t] != kCollapsed; });

  std::vector<std::uint32_t> label(n, kNone);  // indexed by root
  std::vector<ComponentReport> components;
  for (std::size_t t = 0; t < triangleCount; ++t) {
    if (flags[t] == kCollapsed) continue;
    const Triangle& tri = mesh.triangles[t];
    std::uint32_t& l = label[root[tri[0]]];
    if (l == kNone) {
      l = static_cast<std::uint32_t>(components.size());
      components.emplace_back();
    }
    ++components[l].triangles;
    components[l].signedVolume += signedVolumeTerm(mesh, tri);
  }
  std::vector<std::uint8_t> componentFlags(components.size(), 0);
  for (std::size_t v = 0; v < n; ++v) {
    const VertexFigures& fig = figures[v];
    if (!(fig.flags & kReferenced)) continue;
    const std::uint32_t l = label[root[v]];
    ++components[l].vertices;
    components[l].edges += fig.ownedEdges;
    componentFlags[l] |= fig.flags;
  }
  for (std::size_t c = 0; c < components.size(); ++c) {
    ComponentReport& comp = components[c];
    comp.eulerCharacteristic = comp.vertices - comp.edges + comp.triangles;
    comp.closed = !(componentFlags[c] & (kBoundaryEdge | kNonManifoldEdge));
    comp.manifold = !(componentFlags[c] & (kNonManifoldEdge | kNonManifoldVertex));
    const std::int64_t twiceGenus = 2 - comp.eulerCharacteristic;
    comp.genus = comp.closed && comp.manifold && twiceGenus >= 0 && twiceGenus % 2 == 0 ? twiceGenus / 2 : -1;
  }
  return components;
}

}  // namespace

MeshReport validateMesh(const Mesh& mesh, const ValidateOptions& options) {
  if (mesh.triangles.size() >= kNone || mesh.positions.size() >= kNone)
    throw InputError("validateMesh: the mesh has " + std::to_string(mesh.positions.size()) + " vertices and " +
                     std::to_string(mesh.triangles.size()) + " triangles; at most 2^32 - 2 of each are supported");
  MeshReport report;
  report.vertices = static_cast<std::int64_t>(mesh.positions.size());
  report.triangles = static_cast<std::int64_t>(mesh.triangles.size());

  const std::vector<std::uint8_t> flags = classifyTriangles(mesh);
  std::int64_t collapsedCount = 0;
  for (const std::uint8_t f : flags) {
    collapsedCount += f == kCollapsed;
    report.degenerateTriangles += f != kProper;
  }

  std::vector<VertexFigures> figures(mesh.positions.size());
  Totals totals;
  {
    const Stars stars = buildStars(mesh, flags);
    totals = analyseUmbrellas(stars, figures);
  }
  report.referencedVertices = totals.referencedVertices;
  report.edges = totals.edges;
  report.boundaryEdges = totals.boundaryEdges;
  report.nonManifoldEdges = totals.nonManifoldEdges;
  report.nonManifoldVertices = totals.nonManifoldVertices;
  report.inconsistentlyOrientedEdges = totals.inconsistentEdges;
  report.eulerCharacteristic = report.referencedVertices - report.edges + (report.triangles - collapsedCount);
  report.closed = report.boundaryEdges == 0 && report.nonManifoldEdges == 0;
  report.manifold = report.nonManifoldEdges == 0 && report.nonManifoldVertices == 0;

  report.componentReports = buildComponents(mesh, flags, figures);
  report.components = static_cast<std::int64_t>(report.componentReports.size());
  for (const ComponentReport& c : report.componentReports) report.signedVolume += c.signedVolume;

  if (options.selfIntersections) report.selfIntersectingPairs = countSelfIntersections(mesh);
  return report;
}

}  // namespace isovdb::mesh
