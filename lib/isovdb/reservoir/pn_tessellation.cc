// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/pn_tessellation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>
#include <unordered_map>

#include "isovdb/errors.h"
#include "isovdb/mesh/self_intersection.h"
#include "isovdb/reservoir/pn_triangle.h"

namespace isovdb::reservoir {
namespace {

Vec3d toVec(const mesh::Vec3f& v) { return {v[0], v[1], v[2]}; }
mesh::Vec3f toFloat(const Vec3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}
std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

}  // namespace

double edgeSubdivisions(double cosine, int maxFactor, FactorRule rule) {
  const double t = std::clamp(cosine, -1.0, 1.0);
  if (rule == FactorRule::Linear) return maxFactor * (1 - t) * 0.5;
  const double t1 = (t + 1) * 0.5;
  const double t2 = (1 - t1) * 0.45 + t1;
  return std::pow(6.0, 1.0 / t2) - 5.0;
}

int edgeFactor(const Vec3d& ni, const Vec3d& nj, int maxFactor, FactorRule rule) {
  const double s = std::min(edgeSubdivisions(ni.dot(nj), maxFactor, rule), static_cast<double>(maxFactor));
  // A tiny tolerance so that parallel normals (e = 1 up to rounding) give 1.
  return std::clamp(static_cast<int>(std::ceil(s - 1e-9)), 1, maxFactor);
}

namespace {

/// The input's edges: their factors, and their numbers (in key order) for the edge points.
struct EdgeTable {
  std::map<std::uint64_t, int> factors;
  std::map<std::uint64_t, std::uint32_t> index;
};

/// One tessellation of `input`, the edges in `straight` (edgeKey) kept as chords; the input
/// triangle of each output triangle in `source`.
mesh::Mesh tessellateOnce(const mesh::Mesh& input, const EdgeTable& edges, double inflation,
                          const std::set<std::uint64_t>& straight, std::vector<std::uint32_t>& source) {
  const auto& factors = edges.factors;
  const auto& edgeIndex = edges.index;
  mesh::Mesh out;
  out.positions = input.positions;
  out.normals = input.normals;
  source.clear();
  std::unordered_map<std::uint64_t, std::uint32_t> edgePoints;  // (edge index << 8 | q) -> vertex
  std::vector<std::uint32_t> grid;
  for (std::uint32_t triangle = 0; triangle < input.triangles.size(); ++triangle) {
    const auto& t = input.triangles[triangle];
    std::array<Vec3d, 3> p, nrm, inflated;
    std::array<bool, 3> chord{};
    for (int c = 0; c < 3; ++c) {
      p[c] = toVec(input.positions[t[c]]);
      nrm[c] = toVec(input.normals[t[c]]).normalized();
      inflated[c] = p[c] + inflation * nrm[c];
      chord[c] = straight.count(edgeKey(t[c], t[(c + 1) % 3])) != 0;
    }
    const PnTriangle patch(p, nrm, chord), envelope(inflated, nrm, chord);
    std::array<int, 3> f;  // edge c: corners c -> c+1
    for (int c = 0; c < 3; ++c) f[c] = factors.at(edgeKey(t[c], t[(c + 1) % 3]));
    const int n = std::max({f[0], f[1], f[2]});
    // Grid point (j, k): weights (n-j-k, j, k)/n of corners 0, 1, 2.
    auto at = [&](int j, int k) -> std::uint32_t& { return grid[static_cast<std::size_t>(k) * (n + 1) + j]; };
    grid.assign(static_cast<std::size_t>(n + 1) * (n + 1), 0);
    auto emit = [&](const std::array<double, 3>& w) {
      out.positions.push_back(toFloat(patch.position(w[0], w[1], w[2])));
      out.normals.push_back(toFloat(envelopeNormal(patch, envelope, w[0], w[1], w[2])));
      return static_cast<std::uint32_t>(out.positions.size() - 1);
    };
    // The point q of edge c's own f[c] steps from its lower-index end, shared by both
    // triangles of the edge.
    const auto edgeVertex = [&](int c, int q) {
      const std::uint32_t a = t[c], b = t[(c + 1) % 3], low = std::min(a, b), high = std::max(a, b);
      if (q == 0) return low;
      if (q == f[c]) return high;
      const std::uint64_t key = (static_cast<std::uint64_t>(edgeIndex.at(edgeKey(a, b))) << 8) | q;
      if (const auto found = edgePoints.find(key); found != edgePoints.end()) return found->second;
      const double s = static_cast<double>(q) / f[c];  // from the low end
      std::array<double, 3> bary{0, 0, 0};
      bary[a == low ? c : (c + 1) % 3] = 1 - s;
      bary[a == low ? (c + 1) % 3 : c] = s;
      return edgePoints[key] = emit(bary);
    };
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      if (a != b && b != c && a != c) {
        out.triangles.push_back({a, b, c});
        source.push_back(triangle);
      }
    };
    if (chord[0] && chord[1] && chord[2]) {
      // Flat: its edges' points fanned from its centroid. The grid's points snapped to the
      // edges' own factors folded thin triangles over themselves (Reek PORO 0.15, k = 6: 3
      // pairs inside one input triangle once every patch around was straight).
      std::vector<std::uint32_t> ring;
      for (int c = 0; c < 3; ++c)
        for (int step = 0; step < f[c]; ++step)
          ring.push_back(edgeVertex(c, t[c] < t[(c + 1) % 3] ? step : f[c] - step));
      const std::uint32_t centre = emit({1.0 / 3, 1.0 / 3, 1.0 / 3});
      for (std::size_t r = 0; r < ring.size(); ++r) add(centre, ring[r], ring[(r + 1) % ring.size()]);
      continue;
    }
    for (int k = 0; k <= n; ++k)
      for (int j = 0; j + k <= n; ++j) {
        const int i = n - j - k;
        const std::array<int, 3> w{i, j, k};
        int zeros = 0, corner = -1;
        for (int c = 0; c < 3; ++c) {
          zeros += w[c] == 0;
          if (w[c] == n) corner = c;
        }
        if (corner >= 0) {
          at(j, k) = t[corner];
        } else if (zeros == 1) {
          // On edge c (corners c, c+1): the corner with weight 0 is c+2.
          int c = 0;
          while (w[(c + 2) % 3] != 0) ++c;
          const int fromLow = t[c] < t[(c + 1) % 3] ? w[(c + 1) % 3] : w[c];  // steps from the lower-index end
          at(j, k) = edgeVertex(c, (2 * fromLow * f[c] + n) / (2 * n));       // snapped to the edge's own factor
        } else {
          at(j, k) = emit({static_cast<double>(i) / n, static_cast<double>(j) / n, static_cast<double>(k) / n});
        }
      }
    for (int k = 0; k < n; ++k)
      for (int j = 0; j + k < n; ++j) {
        add(at(j, k), at(j + 1, k), at(j, k + 1));
        if (j + k + 2 <= n) add(at(j + 1, k), at(j + 1, k + 1), at(j, k + 1));
      }
  }
  return out;
}

}  // namespace

TessellationResult tessellatePn(const mesh::Mesh& input, const TessellationOptions& options) {
  if (input.normals.size() != input.positions.size()) throw InputError("PN tessellation needs one normal per vertex");
  if (options.maxFactor < 1 || options.maxFactor > 255)
    throw InputError("PN tessellation: the maximum factor must be between 1 and 255");
  TessellationResult result;
  // Edge factors and the mean edge length (for the envelope offset).
  EdgeTable edges;
  auto& factors = edges.factors;
  double lengthSum = 0;
  for (const auto& t : input.triangles)
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = t[e], b = t[(e + 1) % 3];
      const auto [it, inserted] = factors.emplace(edgeKey(a, b), 0);
      if (!inserted) continue;
      it->second = edgeFactor(toVec(input.normals[a]).normalized(), toVec(input.normals[b]).normalized(),
                              options.maxFactor, options.rule);
      lengthSum += (toVec(input.positions[a]) - toVec(input.positions[b])).norm();
    }
  result.edges = static_cast<std::int64_t>(factors.size());
  double factorSum = 0;
  for (const auto& [key, f] : factors) factorSum += f;
  result.meanFactor = factors.empty() ? 0 : factorSum / factors.size();
  const double inflation = options.inflation * (factors.empty() ? 0 : lengthSum / factors.size());
  for (const auto& [key, f] : factors) edges.index.emplace(key, static_cast<std::uint32_t>(edges.index.size()));

  std::set<std::uint64_t> straight;
  std::vector<std::uint32_t> source;
  result.mesh = tessellateOnce(input, edges, inflation, straight, source);
  if (!options.straightenCrossings) return result;
  // Patches that cross others: their triangles' edges become chords (both triangles of an
  // edge follow it, so no crack opens), pass after pass while a pass straightens something.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  result.pairsBefore = result.pairsAfter = mesh::countSelfIntersections(result.mesh, &pairs);
  for (int pass = 0; pass < options.maxStraighteningPasses && !pairs.empty(); ++pass) {
    const std::size_t before = straight.size();
    for (const auto& [x, y] : pairs)
      for (const std::uint32_t t : {source[x], source[y]})
        for (int c = 0; c < 3; ++c) straight.insert(edgeKey(input.triangles[t][c], input.triangles[t][(c + 1) % 3]));
    if (straight.size() == before) break;
    result.mesh = tessellateOnce(input, edges, inflation, straight, source);
    result.pairsAfter = mesh::countSelfIntersections(result.mesh, &pairs);
  }
  result.straightEdges = static_cast<std::int64_t>(straight.size());
  return result;
}

}  // namespace isovdb::reservoir
