// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/untangle_loops.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include "isovdb/mesh/self_intersection.h"
#include "isovdb/mesh/triangle_grid.h"
#include "isovdb/union_find.h"

namespace isovdb::reservoir {
namespace {

using mesh::Triangle;

struct Box {
  std::array<float, 3> lo{}, hi{};
  bool overlaps(const Box& other) const {
    for (int k = 0; k < 3; ++k)
      if (lo[k] > other.hi[k] || other.lo[k] > hi[k]) return false;
    return true;
  }
};

Box boxOf(const mesh::Mesh& m, const Triangle& t) {
  Box box;
  for (int k = 0; k < 3; ++k) {
    box.lo[k] = std::min({m.positions[t[0]][k], m.positions[t[1]][k], m.positions[t[2]][k]});
    box.hi[k] = std::max({m.positions[t[0]][k], m.positions[t[1]][k], m.positions[t[2]][k]});
  }
  return box;
}

/// A triangle with no area to speak of (a fan across three nearly collinear loop vertices):
/// never a better choice, though the exact test skips it.
bool sliver(const mesh::Mesh& m, const Triangle& t) {
  const auto& a = m.positions[t[0]];
  const auto& b = m.positions[t[1]];
  const auto& c = m.positions[t[2]];
  const std::array<double, 3> u{double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
  const std::array<double, 3> v{double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
  const std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double area2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  const double longest = std::max({u[0] * u[0] + u[1] * u[1] + u[2] * u[2], v[0] * v[0] + v[1] * v[1] + v[2] * v[2]});
  return !(area2 > 1e-12 * longest * longest);
}

/// The boundary of edge-connected triangles as one cycle of vertices in their winding, or
/// nothing where it is not one simple cycle.
std::optional<std::vector<std::uint32_t>> boundaryCycle(const std::vector<Triangle>& triangles) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> directed;
  for (const Triangle& t : triangles)
    for (int e = 0; e < 3; ++e) directed.emplace_back(t[e], t[(e + 1) % 3]);
  std::sort(directed.begin(), directed.end());
  std::map<std::uint32_t, std::uint32_t> next;
  for (const auto& [from, to] : directed)
    if (!std::binary_search(directed.begin(), directed.end(), std::pair{to, from}))
      if (!next.emplace(from, to).second) return std::nullopt;  // a vertex the boundary passes twice
  if (next.size() < 3) return std::nullopt;
  std::vector<std::uint32_t> cycle{next.begin()->first};
  while (cycle.size() <= next.size()) {
    const auto found = next.find(cycle.back());
    if (found == next.end()) return std::nullopt;
    if (found->second == cycle.front()) break;
    cycle.push_back(found->second);
  }
  if (cycle.size() != next.size()) return std::nullopt;  // more than one cycle
  return cycle;
}

/// The triangles of one cell, split into edge-connected groups (one per loop).
std::vector<std::vector<std::uint32_t>> loopsOf(const mesh::Mesh& m, const std::vector<std::uint32_t>& triangles) {
  std::vector<std::size_t> parent(triangles.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t i = 0; i < triangles.size(); ++i)
    for (std::size_t j = i + 1; j < triangles.size(); ++j) {
      const Triangle& a = m.triangles[triangles[i]];
      const Triangle& b = m.triangles[triangles[j]];
      int shared = 0;
      for (const auto va : a) shared += va == b[0] || va == b[1] || va == b[2];
      if (shared >= 2) parent[findRoot(parent, i)] = findRoot(parent, j);
    }
  std::map<std::size_t, std::vector<std::uint32_t>> groups;
  for (std::size_t i = 0; i < triangles.size(); ++i) groups[findRoot(parent, i)].push_back(triangles[i]);
  std::vector<std::vector<std::uint32_t>> loops;
  for (auto& [first, group] : groups) loops.push_back(std::move(group));
  return loops;
}

/// One pass over the cells of the pairs; returns the loops fanned again.
std::int64_t refanPass(mesh::Mesh& m, std::vector<std::uint32_t>& triangleCells,
                       const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) {
  std::vector<std::uint32_t> cells;
  for (const auto& [a, b] : pairs) {
    cells.push_back(triangleCells[a]);
    cells.push_back(triangleCells[b]);
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::vector<std::vector<std::uint32_t>> cellTriangles(cells.size());
  for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
    if (const auto it = std::lower_bound(cells.begin(), cells.end(), triangleCells[t]);
        it != cells.end() && *it == triangleCells[t])
      cellTriangles[static_cast<std::size_t>(it - cells.begin())].push_back(t);

  const std::size_t count = m.triangles.size();
  std::vector<Box> boxes(count);
  for (std::size_t t = 0; t < count; ++t) boxes[t] = boxOf(m, m.triangles[t]);
  // Bins about the mean triangle box's size: the triangles around a loop without a pass over
  // the whole mesh (thousands of loops on a mesh of millions would take that many passes).
  double extent = 0;
  for (const Box& b : boxes)
    for (int k = 0; k < 3; ++k) extent += double(b.hi[k]) - b.lo[k];
  const mesh::TriangleGrid grid(m,
                                std::max(extent / (3.0 * static_cast<double>(std::max<std::size_t>(count, 1))), 1e-30));
  std::vector<std::uint8_t> removed(count, 0);
  std::map<std::uint32_t, std::vector<Triangle>> replacement;  // at a loop's first triangle
  std::vector<Triangle> added;                                 // every replacement, for later loops
  std::int64_t refanned = 0;
  // How many crossings the triangles `candidate` of a loop make with the triangles around it
  // (those in `around`, and the added ones whose boxes meet the loop's) and among themselves.
  const auto crossings = [&](const std::vector<Triangle>& candidate, const std::vector<std::uint32_t>& around,
                             const Box& loopBox) {
    std::int64_t n = 0;
    for (std::size_t i = 0; i < candidate.size(); ++i) {
      if (sliver(m, candidate[i])) n += 1000;
      const Box box = boxOf(m, candidate[i]);
      for (const std::uint32_t t : around)
        n += !removed[t] && box.overlaps(boxes[t]) && mesh::trianglesIntersect(m, candidate[i], m.triangles[t]);
      for (const Triangle& t : added)
        n += loopBox.overlaps(boxOf(m, t)) && mesh::trianglesIntersect(m, candidate[i], t);
      for (std::size_t j = i + 1; j < candidate.size(); ++j)
        n += mesh::trianglesIntersect(m, candidate[i], candidate[j]);
    }
    return n;
  };
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (const std::vector<std::uint32_t>& loop : loopsOf(m, cellTriangles[c])) {
      std::vector<Triangle> current;
      for (const std::uint32_t t : loop) current.push_back(m.triangles[t]);
      const auto cycle = boundaryCycle(current);
      if (!cycle) continue;
      const std::size_t n = cycle->size();
      Box loopBox = boxOf(m, current.front());
      for (const Triangle& t : current) {
        const Box box = boxOf(m, t);
        for (int k = 0; k < 3; ++k) {
          loopBox.lo[k] = std::min(loopBox.lo[k], box.lo[k]);
          loopBox.hi[k] = std::max(loopBox.hi[k], box.hi[k]);
        }
      }
      std::vector<std::uint32_t> around;
      for (const std::uint32_t t : grid.trianglesNear({loopBox.lo[0], loopBox.lo[1], loopBox.lo[2]},
                                                      {loopBox.hi[0], loopBox.hi[1], loopBox.hi[2]}))
        if (!removed[t] && std::find(loop.begin(), loop.end(), t) == loop.end()) around.push_back(t);
      std::int64_t best = crossings(current, around, loopBox);
      if (best == 0) continue;
      // A diagonal that is already an edge around the loop (another cell's fan between two
      // crossings of their shared face) would give that edge four triangles.
      const auto edgeAround = [&](std::uint32_t a, std::uint32_t b) {
        const auto holds = [&](const Triangle& t) {
          return (t[0] == a || t[1] == a || t[2] == a) && (t[0] == b || t[1] == b || t[2] == b);
        };
        return std::any_of(around.begin(), around.end(),
                           [&](std::uint32_t t) { return !removed[t] && holds(m.triangles[t]); }) ||
               std::any_of(added.begin(), added.end(), holds);
      };
      std::optional<std::vector<Triangle>> chosen;
      for (std::size_t apex = 0; apex < n; ++apex) {
        bool shared = false;
        for (std::size_t k = 2; k + 1 < n && !shared; ++k)
          shared = edgeAround((*cycle)[apex], (*cycle)[(apex + k) % n]);
        if (shared) continue;
        std::vector<Triangle> fan;
        for (std::size_t k = 1; k + 1 < n; ++k)
          fan.push_back({(*cycle)[apex], (*cycle)[(apex + k) % n], (*cycle)[(apex + k + 1) % n]});
        if (const std::int64_t score = crossings(fan, around, loopBox); score < best) {
          best = score;
          chosen = std::move(fan);
        }
      }
      if (!chosen) continue;
      for (const std::uint32_t t : loop) removed[t] = 1;
      added.insert(added.end(), chosen->begin(), chosen->end());
      replacement[*std::min_element(loop.begin(), loop.end())] = std::move(*chosen);
      ++refanned;
    }
  if (refanned == 0) return 0;

  std::vector<Triangle> triangles;
  std::vector<std::uint32_t> cellsOut;
  triangles.reserve(count);
  cellsOut.reserve(count);
  for (std::uint32_t t = 0; t < count; ++t) {
    if (!removed[t]) {
      triangles.push_back(m.triangles[t]);
      cellsOut.push_back(triangleCells[t]);
    } else if (const auto it = replacement.find(t); it != replacement.end()) {
      for (const Triangle& r : it->second) {
        triangles.push_back(r);
        cellsOut.push_back(triangleCells[t]);
      }
    }
  }
  m.triangles = std::move(triangles);
  triangleCells = std::move(cellsOut);
  return refanned;
}

/// Removes the vertices no triangle uses (and their normals), renumbering the rest in order.
void dropUnusedVertices(mesh::Mesh& m) {
  std::vector<std::uint32_t> newIndex(m.positions.size(), 0);
  for (const Triangle& t : m.triangles)
    for (const auto v : t) newIndex[v] = 1;
  if (std::all_of(newIndex.begin(), newIndex.end(), [](std::uint32_t used) { return used != 0; })) return;
  std::uint32_t kept = 0;
  for (std::size_t v = 0; v < newIndex.size(); ++v) {
    if (!newIndex[v]) continue;
    m.positions[kept] = m.positions[v];
    if (!m.normals.empty()) m.normals[kept] = m.normals[v];
    newIndex[v] = kept++;
  }
  m.positions.resize(kept);
  if (!m.normals.empty()) m.normals.resize(kept);
  for (Triangle& t : m.triangles)
    for (auto& v : t) v = newIndex[v];
}

}  // namespace

UntangleResult untangleLoops(mesh::Mesh& mesh, std::vector<std::uint32_t>& triangleCells) {
  UntangleResult result;
  auto& pairs = result.remainingPairs;
  result.pairsBefore = result.pairsAfter = mesh::countSelfIntersections(mesh, &pairs);
  // Pairs everywhere (cells folded over each other: random ZCORN on 40 x 40 x 10 cells, 9,680
  // pairs in 34,324 triangles, 3 s to bring them to 5,345) are the grid's, not the fans'.
  result.skipped = pairs.size() > 1000 + mesh.triangles.size() / 100;
  for (int pass = 0; pass < 3 && !pairs.empty() && !result.skipped; ++pass) {
    const std::int64_t refanned = refanPass(mesh, triangleCells, pairs);
    if (refanned == 0) break;
    result.loopsRefanned += refanned;
    result.pairsAfter = mesh::countSelfIntersections(mesh, &pairs);
  }
  dropUnusedVertices(mesh);  // triangles keep their places: the pairs stay true
  return result;
}

}  // namespace isovdb::reservoir
