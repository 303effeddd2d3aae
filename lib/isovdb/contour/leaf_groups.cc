#include "isovdb/contour/leaf_groups.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "isovdb/octree/criteria.h"

namespace isovdb::contour {

namespace {

constexpr std::size_t kGrain = 256;

/// Configuration of the cell [origin, origin + size], or -1 if it leaves the samples' apron.
int cellConfigAt(const octree::MetaCellSamples& samples, const std::array<int, 3>& origin, int size,
                 float iso) noexcept {
  for (int a = 0; a < 3; ++a)
    if (origin[a] < -samples.apron || origin[a] + size > samples.size + samples.apron) return -1;
  return octree::cellCornerSigns(samples, origin, size, iso);
}

}  // namespace

LeafGroups groupLeaves(const octree::MetaCellSamples& samples, const octree::LinearOctree& tree,
                       std::vector<std::uint8_t> configs, float iso, bool manifoldFix) {
  const std::size_t n = tree.leafCount();
  LeafGroups groups;
  groups.configs = std::move(configs);
  groups.alternative.assign(n, 0);
  std::vector<char> beyondApron(n, 0);
  if (manifoldFix) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        const int face = dmcEntry(groups.configs[i]).doubleFace;
        if (face < 0) continue;
        const octree::OctreeLeaf& leaf = tree.leaf(i);
        std::array<int, 3> neighbour = leaf.origin;
        neighbour[static_cast<std::size_t>(face >> 1)] += (face & 1) ? leaf.size : -leaf.size;
        const int config = cellConfigAt(samples, neighbour, leaf.size, iso);
        if (config < 0) {
          beyondApron[i] = 1;
          continue;
        }
        groups.alternative[i] = dmcEntry(static_cast<std::uint8_t>(config)).doubleFace == (face ^ 1);
      }
    });
  }
  groups.firstVertex.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    groups.firstVertex[i + 1] = groups.firstVertex[i] + groups.entry(i).vertexCount;
    groups.manifoldFixes += groups.alternative[i];
    groups.fixesBeyondApron += beyondApron[i];
  }
  return groups;
}

std::vector<mesh::Vec3f> placeGroupVertices(const octree::MetaCellSamples& samples, const octree::LinearOctree& tree,
                                            const LeafGroups& groups, const DualVertexOptions& options) {
  std::vector<mesh::Vec3f> positions(groups.totalVertices());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tree.leafCount(), kGrain / 4),
                    [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const DmcEntry& entry = groups.entry(i);
      const octree::OctreeLeaf& leaf = tree.leaf(i);
      if (entry.vertexCount == 1 && !options.massPointOnly &&
          leaf.vertexTruncation == options.singularValueThreshold &&
          leaf.vertexSharpFeatures == options.sharpFeatures) {
        // The construction's geometric criterion solved this QEF already.
        positions[groups.firstVertex[i]] = leaf.vertex;
        continue;
      }
      // Several sheets in one cell: each vertex at its group's mass point, which stays
      // among its own crossings (a QEF minimiser may wander towards the other sheet).
      DualVertexOptions groupOptions = options;
      groupOptions.massPointOnly = entry.vertexCount > 1;
      for (int g = 0; g < entry.vertexCount; ++g) {
        const DualVertex v = computeDualVertex(samples, leaf.origin, leaf.size,
                                               entry.groups[static_cast<std::size_t>(g)], groupOptions);
        mesh::Vec3f p = v.position;
        if (!v.valid())  // cannot happen for bipolar edges; keep the cell centre rather than garbage
          for (std::size_t a = 0; a < 3; ++a)
            p[a] = static_cast<float>(samples.origin[a] + leaf.origin[a]) + 0.5f * static_cast<float>(leaf.size);
        positions[groups.firstVertex[i] + static_cast<std::size_t>(g)] = p;
      }
    }
  });
  return positions;
}

}  // namespace isovdb::contour
