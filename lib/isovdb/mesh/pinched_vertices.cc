// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/mesh/pinched_vertices.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "isovdb/union_find.h"

namespace isovdb::mesh {

namespace {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();
/// How far each copy of a pinched vertex moves towards its own fan (mesh units).
constexpr float kPinchStep = 1e-3f;

}  // namespace

std::size_t splitPinchedVertices(Mesh& mesh) {
  const std::size_t vertexCount = mesh.positions.size();
  // Incident triangles per vertex, in triangle order (counting sort).
  std::vector<std::uint32_t> first(vertexCount + 1, 0);
  for (const Triangle& tri : mesh.triangles)
    for (const std::uint32_t v : tri) ++first[v + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<std::uint32_t> incident(first.back());
  {
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
      for (const std::uint32_t v : mesh.triangles[t]) incident[next[v]++] = static_cast<std::uint32_t>(t);
  }
  std::size_t added = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> opposite;  // (other corner, incidence position)
  std::vector<std::uint32_t> parent, fanVertex;
  for (std::uint32_t v = 0; v < vertexCount; ++v) {
    const std::uint32_t begin = first[v], count = first[v + 1] - begin;
    if (count < 2) continue;
    // Two triangles at v lie in one fan when they share an edge through v: another corner
    // (a union-find over positions in v's incidence list).
    opposite.clear();
    for (std::uint32_t k = 0; k < count; ++k)
      for (const std::uint32_t w : mesh.triangles[incident[begin + k]])
        if (w != v) opposite.emplace_back(w, k);
    std::sort(opposite.begin(), opposite.end());
    parent.resize(count);
    std::iota(parent.begin(), parent.end(), 0u);
    for (std::size_t i = 1; i < opposite.size(); ++i)
      if (opposite[i].first == opposite[i - 1].first)
        parent[findRoot(parent, opposite[i].second)] = findRoot(parent, opposite[i - 1].second);
    const std::uint32_t firstFan = findRoot(parent, 0);
    bool pinched = false;
    for (std::uint32_t k = 1; k < count && !pinched; ++k) pinched = findRoot(parent, k) != firstFan;
    if (!pinched) continue;
    // The fan of the first triangle keeps v; each other fan, met in triangle order, gets a copy.
    fanVertex.assign(count, kNoVertex);
    fanVertex[firstFan] = v;
    const Vec3f at = mesh.positions[v];
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::uint32_t fan = findRoot(parent, k);
      if (fanVertex[fan] == kNoVertex) {
        fanVertex[fan] = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(at);
        if (!mesh.normals.empty()) mesh.normals.push_back(mesh.normals[v]);
        ++added;
      }
      for (std::uint32_t& corner : mesh.triangles[incident[begin + k]])
        if (corner == v) corner = fanVertex[fan];
    }
    // Each copy steps towards its own fan, so the sheets no longer meet at one point.
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::uint32_t fan = findRoot(parent, k);
      if (fan != k) continue;  // once per fan, at its root
      Vec3f towards{0.0f, 0.0f, 0.0f};
      for (std::uint32_t j = 0; j < count; ++j) {
        if (findRoot(parent, j) != fan) continue;
        for (const std::uint32_t w : mesh.triangles[incident[begin + j]])
          if (w != fanVertex[fan])
            for (int a = 0; a < 3; ++a) towards[a] += mesh.positions[w][a] - at[a];
      }
      const float length = std::sqrt(towards[0] * towards[0] + towards[1] * towards[1] + towards[2] * towards[2]);
      if (length <= 0.0f) continue;
      Vec3f& p = mesh.positions[fanVertex[fan]];
      for (int a = 0; a < 3; ++a) p[a] = at[a] + kPinchStep * towards[a] / length;
    }
  }
  return added;
}

}  // namespace isovdb::mesh
