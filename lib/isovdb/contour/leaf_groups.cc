// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/contour/leaf_groups.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "isovdb/contour/adaptive_edges.h"
#include "isovdb/contour/box_caps.h"
#include "isovdb/octree/criteria.h"

namespace isovdb::contour {

namespace {

constexpr std::size_t kGrain = 256;

/// Configuration of the cell [origin, origin + size], or -1 if it leaves the samples' apron.
int cellConfigAt(const cell::MetaCellSamples& samples, const std::array<int, 3>& origin, int size, float iso) noexcept {
  for (int a = 0; a < 3; ++a)
    if (origin[a] < -samples.apron || origin[a] + size > samples.size + samples.apron) return -1;
  return cell::cellCornerSigns(samples, origin, size, iso);
}

}  // namespace

namespace {

/// The fix of doubled faces. MDMC (Wenger): a doubled leaf takes the alternative grouping
/// when the cell across its doubled face is doubled on it too. Voxels: such a face is split,
/// recorded by the leaf on its min side.
void fixDoubledFaces(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree, float iso,
                     LeafGroups& groups, std::vector<char>& beyondApron) {
  const auto entryOf = [&](int config) -> const cell::DmcEntry& {
    const auto c = static_cast<std::uint8_t>(config);
    return groups.voxels ? voxelDmcEntry(c) : cell::dmcEntry(c);
  };
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tree.leafCount(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) {
                        const int face = entryOf(groups.configs[i]).doubleFace;
                        if (face < 0 || (groups.voxels && (face & 1) == 0)) continue;
                        const octree::OctreeLeaf& leaf = tree.leaf(i);
                        std::array<int, 3> neighbour = leaf.origin;
                        neighbour[static_cast<std::size_t>(face >> 1)] += (face & 1) ? leaf.size : -leaf.size;
                        const int config = cellConfigAt(samples, neighbour, leaf.size, iso);
                        if (config < 0) {
                          beyondApron[i] = 1;
                          continue;
                        }
                        if (entryOf(config).doubleFace != (face ^ 1)) continue;
                        if (groups.voxels)
                          groups.splitFaces[i] = static_cast<std::uint8_t>(1u << (face >> 1));
                        else
                          groups.alternative[i] = 1;
                      }
                    });
}

}  // namespace

LeafGroups groupLeaves(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                       std::vector<std::uint8_t> configs, float iso, bool manifoldFix, RegularTopology topology) {
  const std::size_t n = tree.leafCount();
  LeafGroups groups;
  groups.voxels = topology == RegularTopology::Voxels;
  groups.configs = std::move(configs);
  groups.alternative.assign(n, 0);
  if (groups.voxels) groups.splitFaces.assign(n, 0);
  std::vector<char> beyondApron(n, 0);
  if (manifoldFix) fixDoubledFaces(samples, tree, iso, groups, beyondApron);
  groups.firstVertex.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const int splits = groups.voxels ? 2 * countBits(static_cast<unsigned>(groups.splitFaces[i])) : 0;
    groups.firstVertex[i + 1] = groups.firstVertex[i] + static_cast<std::uint32_t>(groups.cellVertexCount(i) + splits);
    groups.manifoldFixes += groups.alternative[i] + splits / 2;
    groups.fixesBeyondApron += beyondApron[i];
  }
  return groups;
}

VoxelEdgeCell voxelEdgeCell(const LeafGroups& groups, std::size_t i, const std::vector<std::uint32_t>& ids,
                            const std::vector<mesh::Vec3f>& positions) {
  const auto id = [&](std::uint32_t v) { return ids.empty() ? v : ids[v]; };
  VoxelEdgeCell cell;
  cell.config = groups.configs[i];
  cell.vertices.fill(kNoVertex);
  cell.splitVertices.fill(kNoVertex);
  const int count = groups.cellVertexCount(i);
  for (int g = 0; g < count; ++g) {
    const std::uint32_t v = groups.firstVertex[i] + static_cast<std::uint32_t>(g);
    cell.vertices[static_cast<std::size_t>(g)] = id(v);
    if (!positions.empty()) cell.positions[static_cast<std::size_t>(g)] = positions[v];
  }
  if (!groups.voxels) return cell;
  cell.splitFaces = groups.splitFaces[i];
  for (int axis = 0; axis < 3; ++axis)
    if ((cell.splitFaces >> axis) & 1)
      for (int slot = 0; slot < 2; ++slot)
        cell.splitVertices[static_cast<std::size_t>(splitVertexSlot(axis, slot))] =
            id(groups.splitVertex(i, axis, slot));
  return cell;
}

std::vector<mesh::Vec3f> placeGroupVertices(const cell::MetaCellSamples& samples, const octree::LinearOctree& tree,
                                            const LeafGroups& groups, const cell::DualVertexOptions& options,
                                            const octree::UnitEdgeCrossings* crossings,
                                            const std::optional<cell::DataBox>& capBox) {
  const auto beyondBox = [&](const octree::OctreeLeaf& leaf) {
    if (!capBox) return false;
    for (std::size_t a = 0; a < 3; ++a) {
      const int lo = samples.origin[a] + leaf.origin[a];
      if (lo < (*capBox)[0][a] || lo + leaf.size > (*capBox)[1][a]) return true;
    }
    return false;
  };
  // Held beside the face it lies beyond, where the cap is (box_caps.h).
  const auto capVertex = [&](const mesh::Vec3f& p, const octree::OctreeLeaf& leaf) {
    const Vec3d q = besideDataBox(Vec3d{p[0], p[1], p[2]}, leaf, samples.origin, *capBox);
    return mesh::Vec3f{static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2])};
  };
  // A cell's own vertices (not split vertices, which lie on their face) strictly inside it,
  // kInteriorMargin from its faces: a QEF minimiser clamped onto the cell's boundary could
  // sit on an edge, on the edge point of that edge's fan (example1.nrrd of scijs/nrrd-js: a
  // vertex at a corner line of its cell, 10 self-intersecting pairs), and Ju–Udeshi's
  // envelopes need the cell points inside.
  const auto strictlyInside = [&](const mesh::Vec3f& p, const octree::OctreeLeaf& leaf) {
    const Vec3d q = cellPointInside(p, leaf, samples.origin);
    return mesh::Vec3f{static_cast<float>(q[0]), static_cast<float>(q[1]), static_cast<float>(q[2])};
  };
  std::vector<mesh::Vec3f> positions(groups.totalVertices());
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, tree.leafCount(), kGrain / 4), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          const cell::DmcEntry& entry = groups.entry(i);
          const octree::OctreeLeaf& leaf = tree.leaf(i);
          const bool hasSplits = groups.voxels && groups.splitFaces[i] != 0;
          const bool capped = beyondBox(leaf);
          if (entry.vertexCount == 1 && !hasSplits && !options.massPointOnly && !capped &&
              leaf.vertexTruncation == options.singularValueThreshold &&
              leaf.vertexSharpFeatures == options.sharpFeatures) {
            // The construction's geometric criterion solved this QEF already.
            positions[groups.firstVertex[i]] = strictlyInside(leaf.vertex, leaf);
            continue;
          }
          // Several sheets in one cell: each vertex at its group's mass point, which stays
          // among its own crossings (a QEF minimiser may wander towards the other sheet).
          // Tube sectors and split faces are pieces of a sheet: their mass points too.
          cell::DualVertexOptions groupOptions = options;
          groupOptions.massPointOnly = entry.vertexCount > 1 || capped;
          groupOptions.positionOnly = true;
          const std::uint8_t config = groups.configs[i];
          const bool tube = groups.voxels && isTubeConfig(config);
          std::array<std::uint16_t, 10> vertexEdges{};
          int count = 0;
          if (tube) {
            for (const std::uint16_t edges : tubeSectors(config).edges)
              vertexEdges[static_cast<std::size_t>(count++)] = edges;
          } else {
            for (int g = 0; g < entry.vertexCount; ++g)
              vertexEdges[static_cast<std::size_t>(count++)] = entry.groups[static_cast<std::size_t>(g)];
          }
          const int groupVertices = count;
          if (groups.voxels)
            for (int axis = 0; axis < 3; ++axis)
              if ((groups.splitFaces[i] >> axis) & 1)
                for (const std::uint16_t edges : splitVertexEdges(config, 2 * axis + 1))
                  vertexEdges[static_cast<std::size_t>(count++)] = edges;
          for (int k = 0; k < count; ++k) {
            cell::DualVertexOptions vertexOptions = groupOptions;
            vertexOptions.massPointOnly = groupOptions.massPointOnly || k >= groupVertices;  // a tube has 2 groups
            const std::uint16_t edges = vertexEdges[static_cast<std::size_t>(k)];
            const cell::DualVertex v =
                octree::cellDualVertex(samples, leaf.origin, leaf.size, edges, vertexOptions, crossings);
            mesh::Vec3f p = v.position;
            if (!v.valid())  // cannot happen for bipolar edges; keep the cell centre rather than garbage
              for (std::size_t a = 0; a < 3; ++a)
                p[a] = static_cast<float>(samples.origin[a] + leaf.origin[a]) + 0.5f * static_cast<float>(leaf.size);
            if (k < groupVertices) p = strictlyInside(p, leaf);
            if (capped) p = capVertex(p, leaf);
            positions[groups.firstVertex[i] + static_cast<std::size_t>(k)] = p;
          }
        }
      });
  return positions;
}

}  // namespace isovdb::contour
