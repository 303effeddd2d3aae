#include "isovdb/contour/regular_contour.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <string>
#include <vector>

#include "isovdb/contour/dmc_table.h"
#include "isovdb/contour/dual_vertex.h"
#include "isovdb/errors.h"
#include "isovdb/octree/morton.h"

namespace isovdb::contour {

namespace {

using octree::LinearOctree;
using octree::MetaCellSamples;
using octree::OctreeLeaf;

constexpr std::size_t kGrain = 256;

/// Corner sign configuration of a cell from the samples (bit c = corner c inside).
std::uint8_t cellConfig(const MetaCellSamples& samples, const OctreeLeaf& leaf, float iso) noexcept {
  std::uint8_t config = 0;
  for (int c = 0; c < 8; ++c) {
    const std::array<int, 3> p{leaf.origin[0] + (c & 1) * leaf.size, leaf.origin[1] + ((c >> 1) & 1) * leaf.size,
                               leaf.origin[2] + ((c >> 2) & 1) * leaf.size};
    if (octree::isInside(samples.value(p), iso)) config = static_cast<std::uint8_t>(config | (1u << c));
  }
  return config;
}

/// Shape quality of a triangle in [0, 1]: 4 sqrt(3) area / sum of squared edge lengths (1 = equilateral).
double triangleQuality(const mesh::Vec3f& a, const mesh::Vec3f& b, const mesh::Vec3f& c) noexcept {
  double u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = double(b[i]) - a[i];
    v[i] = double(c[i]) - a[i];
    w[i] = double(c[i]) - b[i];
  }
  const double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
  const double area2 = std::sqrt(cx * cx + cy * cy + cz * cz);  // twice the area
  const double sum = u[0] * u[0] + u[1] * u[1] + u[2] * u[2] + v[0] * v[0] + v[1] * v[1] + v[2] * v[2] +
                     w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  return sum > 0.0 ? 2.0 * std::sqrt(3.0) * area2 / sum : 0.0;
}

/// One quad per owned edge; vertices in cyclic order, oriented outward.
using Quad = std::array<std::uint32_t, 4>;

struct LeafQuads {
  std::array<Quad, 3> quads{};
  std::uint8_t count = 0;
};

}  // namespace

mesh::Mesh contourRegular(const MetaCellSamples& samples, const LinearOctree& regularTree,
                          const RegularContourOptions& options, RegularContourStats* stats) {
  if (samples.size != regularTree.metaCellSize())
    throw InputError("contourRegular: samples.size " + std::to_string(samples.size) +
                     " differs from the octree's meta-cell size " + std::to_string(regularTree.metaCellSize()));

  const std::size_t n = regularTree.leafCount();
  const auto& leaves = regularTree.leaves();

  // 1. Corner configurations, checked against the tree.
  std::vector<std::uint8_t> configs(n);
  std::vector<char> mismatch(n, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      configs[i] = cellConfig(samples, leaves[i], options.iso);
      mismatch[i] = configs[i] != leaves[i].cornerSigns;
    }
  });
  if (const auto it = std::find(mismatch.begin(), mismatch.end(), char{1}); it != mismatch.end())
    throw InputError("contourRegular: leaf " + std::to_string(it - mismatch.begin()) +
                     " has corner signs that differ from the samples at iso " + std::to_string(options.iso) +
                     " (octree built with another isovalue)");

  // 2. Wenger's manifold fix: both cells of a doubled ambiguous face take the alternative grouping.
  std::vector<char> alternative(n, 0);
  if (options.manifoldFix) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        const int face = dmcEntry(configs[i]).doubleFace;
        if (face < 0) continue;
        const octree::MortonKey nk = octree::faceNeighbourKey(leaves[i].key, face);
        if (nk == octree::kInvalidKey) continue;  // meta-cell boundary: left to seam stitching
        const std::int64_t j = regularTree.findLeaf(nk);
        if (j == LinearOctree::kNone) continue;
        alternative[i] = dmcEntry(configs[static_cast<std::size_t>(j)]).doubleFace == (face ^ 1);
      }
    });
  }
  auto entryOf = [&](std::size_t i) -> const DmcEntry& { return dmcEntry(configs[i], alternative[i] != 0); };

  // 3. Vertex numbering: leaves in stored order, table groups in order.
  std::vector<std::uint32_t> vertexBase(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) vertexBase[i + 1] = vertexBase[i] + entryOf(i).vertexCount;
  const std::size_t vertexCount = vertexBase[n];

  mesh::Mesh out;
  out.positions.resize(vertexCount);
  const DualVertexOptions vertexOptions{.iso = options.iso, .singularValueThreshold = options.singularValueThreshold};
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain / 4), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const DmcEntry& entry = entryOf(i);
      const OctreeLeaf& leaf = leaves[i];
      for (int g = 0; g < entry.vertexCount; ++g) {
        const DualVertex v = computeDualVertex(samples, leaf.origin, leaf.size, entry.groups[static_cast<std::size_t>(g)],
                                               vertexOptions);
        mesh::Vec3f p = v.position;
        if (!v.valid()) {  // cannot happen for bipolar edges; keep the cell centre rather than garbage
          for (int a = 0; a < 3; ++a)
            p[static_cast<std::size_t>(a)] = float(samples.origin[static_cast<std::size_t>(a)] +
                                                   leaf.origin[static_cast<std::size_t>(a)]) + 0.5f * float(leaf.size);
        }
        out.positions[vertexBase[i] + static_cast<std::size_t>(g)] = p;
      }
    }
  });

  // 4. Quads: each interior bipolar edge by its owner leaf (the edge is the owner's local edge 4 * axis).
  std::vector<LeafQuads> leafQuads(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const std::uint16_t bipolar = octree::bipolarEdgeMask(configs[i]);
      if (bipolar == 0) continue;
      const OctreeLeaf& leaf = leaves[i];
      LeafQuads& lq = leafQuads[i];
      for (int axis = 0; axis < 3; ++axis) {
        const int edge = 4 * axis;
        if (((bipolar >> edge) & 1) == 0) continue;
        const auto around = regularTree.leavesAroundEdge(leaf.origin, axis);
        assert(around[3] == static_cast<std::int64_t>(i));
        if (std::find(around.begin(), around.end(), LinearOctree::kNone) != around.end()) continue;  // boundary
        std::array<std::uint32_t, 4> v{};  // by quadrant
        bool ok = true;
        for (int q = 0; q < 4; ++q) {
          const auto j = static_cast<std::size_t>(around[static_cast<std::size_t>(q)]);
          // The edge is local edge 4 * axis + (3 - q) of the leaf in quadrant q.
          const int local = 4 * axis + (3 - q);
          const int g = entryOf(j).vertexOfEdge[static_cast<std::size_t>(local)];
          if (g < 0 || leaves[j].size != leaf.size) {
            ok = false;  // not a regular octree around this edge (violates the precondition)
            break;
          }
          v[static_cast<std::size_t>(q)] = vertexBase[j] + static_cast<std::uint32_t>(g);
        }
        assert(ok);
        if (!ok) continue;
        // Quadrants 0,1,3,2 turn counter-clockwise in the (u, v) plane: normal +axis for x and z
        // ((u, v, axis) right-handed), -axis for y. Outward = from the inside end to the outside end.
        const bool minEndInside = (configs[i] & 1) != 0;  // corner 0 of the owner is the edge's min end
        const bool plusAxis = minEndInside;                // the normal must point towards +axis
        const bool ccwIsPlus = axis != 1;
        Quad quad{v[0], v[1], v[3], v[2]};
        if (plusAxis != ccwIsPlus) quad = Quad{v[0], v[2], v[3], v[1]};
        lq.quads[lq.count++] = quad;
      }
    }
  });

  std::vector<std::size_t> quadBase(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) quadBase[i + 1] = quadBase[i] + leafQuads[i].count;
  const std::size_t quadCount = quadBase[n];

  // 5. Each quad into two triangles along the diagonal whose worse triangle is better.
  out.triangles.resize(2 * quadCount);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const LeafQuads& lq = leafQuads[i];
      for (int k = 0; k < lq.count; ++k) {
        const Quad& q = lq.quads[static_cast<std::size_t>(k)];
        const auto& p = out.positions;
        const double qa = std::min(triangleQuality(p[q[0]], p[q[1]], p[q[2]]), triangleQuality(p[q[0]], p[q[2]], p[q[3]]));
        const double qb = std::min(triangleQuality(p[q[0]], p[q[1]], p[q[3]]), triangleQuality(p[q[1]], p[q[2]], p[q[3]]));
        const std::size_t t = 2 * (quadBase[i] + static_cast<std::size_t>(k));
        if (qa >= qb) {
          out.triangles[t] = {q[0], q[1], q[2]};
          out.triangles[t + 1] = {q[0], q[2], q[3]};
        } else {
          out.triangles[t] = {q[0], q[1], q[3]};
          out.triangles[t + 1] = {q[1], q[2], q[3]};
        }
      }
    }
  });

  if (stats) {
    RegularContourStats s;
    for (std::size_t i = 0; i < n; ++i) {
      if (entryOf(i).vertexCount > 0) ++s.cells;
      if (alternative[i]) ++s.manifoldFixes;
    }
    s.vertices = static_cast<std::int64_t>(vertexCount);
    s.quads = static_cast<std::int64_t>(quadCount);
    *stats = s;
  }
  return out;
}

}  // namespace isovdb::contour
