// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/octree/criteria.h on hand-built voxel faces.
#include "isovdb/octree/criteria.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <vector>

namespace isovdb::octree {
namespace {

constexpr float kOut = 1.0f;
constexpr float kIn = -1.0f;

/// A 16^3 block all outside; the cell under test is (0,0,0) with side 8, and
/// its bottom face (z = 0, face index 4) is painted by the tests.
cell::MetaCellSamples outsideBlock() {
  cell::MetaCellSamples s;
  s.allocate(16, {0, 0, 0}, kOut);
  return s;
}

/// The samples' phases at iso 0, what the criteria read.
SamplePhases phasesOf(const cell::MetaCellSamples& s) { return SamplePhases(s, 0.0f); }

constexpr int kBottomFace = 4;  // 2 * axis(z) + side(min)

TEST(Criteria, CountSignChanges) {
  cell::MetaCellSamples s = outsideBlock();
  EXPECT_EQ(countSignChanges(phasesOf(s), {0, 0, 0}, 0, 8), 0);
  s.value(8, 0, 0) = kIn;
  EXPECT_EQ(countSignChanges(phasesOf(s), {0, 0, 0}, 0, 8), 1);
  s.value(8, 0, 0) = 0.0f;  // exactly iso counts as inside
  EXPECT_EQ(countSignChanges(phasesOf(s), {0, 0, 0}, 0, 8), 1);
  EXPECT_FALSE(isComplexEdge(phasesOf(s), {0, 0, 0}, 0, 8));
}

TEST(Criteria, EdgeCrossedThreeTimesIsComplex) {
  cell::MetaCellSamples s = outsideBlock();
  // Along the x edge at y = z = 0: out out in in out out in in in -> 3 changes.
  for (int x : {2, 3, 6, 7, 8}) s.value(x, 0, 0) = kIn;
  EXPECT_EQ(countSignChanges(phasesOf(s), {0, 0, 0}, 0, 8), 3);
  EXPECT_TRUE(isComplexEdge(phasesOf(s), {0, 0, 0}, 0, 8));
  FaceLabeller labeller;
  const CellTopology t = classifyCell(phasesOf(s), {0, 0, 0}, 8, {}, labeller);
  EXPECT_EQ(t.complexEdges, 1u << cellEdgeIndex(0, 0));
  EXPECT_TRUE(t.isComplex());
  EXPECT_TRUE(t.isHeterogeneous());
  EXPECT_EQ(t.cornerSigns, 1u << 1);  // corner (8,0,0) inside
}

TEST(Criteria, IsolatedIslandMakesAComplexFace) {
  cell::MetaCellSamples s = outsideBlock();
  for (int y = 3; y <= 4; ++y)
    for (int x = 3; x <= 5; ++x) s.value(x, y, 0) = kIn;
  FaceLabeller labeller;
  const FaceLabeller::Result r = labeller.label(phasesOf(s), {0, 0, 0}, 2, 8);
  EXPECT_TRUE(r.isolatedComponent);
  EXPECT_FALSE(r.uniform);
  const CellTopology t = classifyCell(phasesOf(s), {0, 0, 0}, 8, {}, labeller);
  EXPECT_EQ(t.complexEdges, 0);
  EXPECT_EQ(t.complexFaces, 1u << kBottomFace);
  EXPECT_TRUE(t.isComplex());
  EXPECT_EQ(t.cornerSigns, 0);  // invisible from the corners and the edges
  // The same island touching an edge is no longer isolated.
  for (int x = 0; x <= 3; ++x) s.value(x, 3, 0) = kIn;
  EXPECT_FALSE(labeller.label(phasesOf(s), {0, 0, 0}, 2, 8).isolatedComponent);
}

/// Paints a square ring (Chebyshev radius 2) centred at (cx, cy) on face z = 0.
void paintRing(cell::MetaCellSamples& s, int cx, int cy) {
  for (int y = cy - 2; y <= cy + 2; ++y)
    for (int x = cx - 2; x <= cx + 2; ++x)
      if (std::max(std::abs(x - cx), std::abs(y - cy)) == 2) s.value(x, y, 0) = kIn;
}

TEST(Criteria, RingTouchingOneEdgeHasAComplexEdge) {
  // Ring x in [0, 4], y in [2, 6]: it lies along the edge x = 0 (y axis) in
  // the middle of it, so that edge changes sign twice; its hole is isolated.
  cell::MetaCellSamples s = outsideBlock();
  paintRing(s, 2, 4);
  EXPECT_EQ(countSignChanges(phasesOf(s), {0, 0, 0}, 1, 8), 2);
  FaceLabeller labeller;
  EXPECT_TRUE(labeller.label(phasesOf(s), {0, 0, 0}, 2, 8).isolatedComponent);  // the hole
  const CellTopology t = classifyCell(phasesOf(s), {0, 0, 0}, 8, {}, labeller);
  EXPECT_EQ(t.complexEdges, 1u << cellEdgeIndex(1, 0));
  EXPECT_EQ(t.complexFaces, 0);  // a face with a complex edge is not a "complex face"
  EXPECT_FALSE(t.facesEvaluated);
  EXPECT_TRUE(t.isComplex());
}

TEST(Criteria, RingTouchingEdgesOnceHasAComplexFaceThroughItsHole) {
  // Ring x, y in [0, 4] around the corner: each of the two edges it touches
  // changes sign once (no complex edge), but the hole is an isolated outside
  // component, a closed contour loop that the edges cannot see.
  cell::MetaCellSamples s = outsideBlock();
  paintRing(s, 2, 2);
  EXPECT_EQ(countSignChanges(phasesOf(s), {0, 0, 0}, 0, 8), 1);
  EXPECT_EQ(countSignChanges(phasesOf(s), {0, 0, 0}, 1, 8), 1);
  FaceLabeller labeller;
  const CellTopology t = classifyCell(phasesOf(s), {0, 0, 0}, 8, {}, labeller);
  EXPECT_EQ(t.complexEdges, 0);
  EXPECT_EQ(t.complexFaces, 1u << kBottomFace);
  EXPECT_TRUE(t.isComplex());
  // Filling the hole removes the complexity: one component touching two edges.
  for (int y = 1; y <= 3; ++y)
    for (int x = 1; x <= 3; ++x) s.value(x, y, 0) = kIn;
  const CellTopology filled = classifyCell(phasesOf(s), {0, 0, 0}, 8, {}, labeller);
  EXPECT_FALSE(filled.isComplex());
  EXPECT_TRUE(filled.isHeterogeneous());
}

TEST(Criteria, InteriorBlobIsDetectedOnlyWhenAsked) {
  cell::MetaCellSamples s = outsideBlock();
  s.value(4, 4, 4) = kIn;
  FaceLabeller labeller;
  const CellTopology with = classifyCell(phasesOf(s), {0, 0, 0}, 8, {.detectInteriorComponents = true}, labeller);
  EXPECT_TRUE(with.boundaryUniform);
  EXPECT_TRUE(with.interiorComponent);
  EXPECT_TRUE(with.isComplex());
  const CellTopology without = classifyCell(phasesOf(s), {0, 0, 0}, 8, {.detectInteriorComponents = false}, labeller);
  EXPECT_FALSE(without.isComplex());
  EXPECT_FALSE(without.isHeterogeneous());
}

TEST(Criteria, BubbleInACellCrossedByTheSurfaceIsHidden) {
  // A plane crosses the 8-cell (its faces are not one phase, so classifyCell does not
  // look inside); a 1-voxel outside bubble below it touches no face.
  cell::MetaCellSamples s = cell::makeMetaCellSamples(16, {0, 0, 0}, [](int, int, int z) { return z - 5.5f; });
  FaceLabeller labeller;
  const CellTopology plane = classifyCell(phasesOf(s), {0, 0, 0}, 8, {}, labeller);
  EXPECT_FALSE(plane.isComplex());
  EXPECT_FALSE(plane.boundaryUniform);
  EXPECT_FALSE(hasHiddenComponent(phasesOf(s), {0, 0, 0}, 8));
  s.value(3, 4, 2) = 1.0f;  // outside, inside the inside half
  EXPECT_FALSE(classifyCell(phasesOf(s), {0, 0, 0}, 8, {}, labeller).isComplex()) << "the face criteria cannot see it";
  EXPECT_TRUE(hasHiddenComponent(phasesOf(s), {0, 0, 0}, 8));
  // On a face it is the face criteria's business, not hidden.
  s.value(3, 4, 2) = -2.5f;
  s.value(0, 4, 2) = 1.0f;
  EXPECT_FALSE(hasHiddenComponent(phasesOf(s), {0, 0, 0}, 8));
  // An inside speck in the outside half.
  s.value(4, 4, 7) = -1.0f;
  EXPECT_TRUE(hasHiddenComponent(phasesOf(s), {0, 0, 0}, 8));
  EXPECT_FALSE(hasHiddenComponent(phasesOf(s), {0, 0, 0}, 1));
}

TEST(Criteria, UniformCellIsSimpleAndHomogeneous) {
  const cell::MetaCellSamples s = outsideBlock();
  FaceLabeller labeller;
  const CellTopology t = classifyCell(phasesOf(s), {8, 8, 8}, 8, {}, labeller);
  EXPECT_FALSE(t.isComplex());
  EXPECT_FALSE(t.isHeterogeneous());
  EXPECT_EQ(t.cornerSigns, 0);
}

/// The criteria written out the slow way, on the float samples: a reference
/// for classifyCell's shortcuts (size-1 and size-2 cells, one-phase cells).
CellTopology referenceTopology(const cell::MetaCellSamples& s, std::array<int, 3> o, int size) {
  auto in = [&](int i, int j, int k) { return s.value(o[0] + i, o[1] + j, o[2] + k) <= 0.0f; };
  CellTopology t;
  for (int c = 0; c < 8; ++c)
    if (in((c & 1) * size, ((c >> 1) & 1) * size, ((c >> 2) & 1) * size)) t.cornerSigns |= 1u << c;
  for (int e = 0; e < 12; ++e) {
    const int c0 = cellEdgeCorner(e, 0), axis = cellEdgeAxis(e);
    std::array<int, 3> p{(c0 & 1) * size, ((c0 >> 1) & 1) * size, ((c0 >> 2) & 1) * size};
    int changes = 0;
    for (int step = 0; step < size; ++step) {
      const bool a = in(p[0], p[1], p[2]);
      ++p[static_cast<std::size_t>(axis)];
      changes += a != in(p[0], p[1], p[2]);
    }
    if (changes > 1) t.complexEdges |= 1u << e;
  }
  if (t.complexEdges) return t;
  t.facesEvaluated = true;
  const bool phase = (t.cornerSigns & 1) != 0;
  bool uniform = true;
  const int n = size + 1;
  for (int f = 0; f < 6; ++f) {
    const int axis = f >> 1;
    const auto uv = otherAxes(axis);
    auto at = [&](int u, int v) {
      std::array<int, 3> p{0, 0, 0};
      p[static_cast<std::size_t>(axis)] = (f & 1) * size;
      p[static_cast<std::size_t>(uv[0])] = u;
      p[static_cast<std::size_t>(uv[1])] = v;
      return in(p[0], p[1], p[2]);
    };
    // Flood each component (4-connectivity) and note whether it reaches the border.
    std::vector<int> seen(static_cast<std::size_t>(n * n), 0);
    for (int start = 0; start < n * n; ++start) {
      if (seen[static_cast<std::size_t>(start)]) continue;
      std::vector<int> stack{start};
      seen[static_cast<std::size_t>(start)] = 1;
      bool border = false;
      const bool ph = at(start % n, start / n);
      while (!stack.empty()) {
        const int q = stack.back();
        stack.pop_back();
        const int u = q % n, v = q / n;
        border |= u == 0 || v == 0 || u == n - 1 || v == n - 1;
        const int du[4] = {1, -1, 0, 0}, dv[4] = {0, 0, 1, -1};
        for (int d = 0; d < 4; ++d) {
          const int a = u + du[d], b = v + dv[d];
          if (a < 0 || b < 0 || a >= n || b >= n || seen[static_cast<std::size_t>(b * n + a)] || at(a, b) != ph)
            continue;
          seen[static_cast<std::size_t>(b * n + a)] = 1;
          stack.push_back(b * n + a);
        }
      }
      if (!border) t.complexFaces |= 1u << f;
    }
    for (int v = 0; v < n; ++v)
      for (int u = 0; u < n; ++u) uniform &= at(u, v) == phase;
  }
  t.boundaryUniform = uniform;
  if (uniform)
    for (int k = 1; k < size; ++k)
      for (int j = 1; j < size; ++j)
        for (int i = 1; i < size; ++i) t.interiorComponent |= in(i, j, k) != phase;
  return t;
}

/// Hidden component, the slow way: breadth-first flood of each phase from the cell's faces.
bool referenceHidden(const cell::MetaCellSamples& s, std::array<int, 3> o, int size) {
  const int n = size + 1;
  auto in = [&](int i, int j, int k) { return s.value(o[0] + i, o[1] + j, o[2] + k) <= 0.0f; };
  std::vector<char> reached(static_cast<std::size_t>(n) * n * n, 0);
  std::vector<std::array<int, 3>> queue;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (i == 0 || j == 0 || k == 0 || i == size || j == size || k == size) {
          reached[(static_cast<std::size_t>(k) * n + j) * n + i] = 1;
          queue.push_back({i, j, k});
        }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const auto [i, j, k] = queue[head];
    const int d[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const auto& e : d) {
      const int a = i + e[0], b = j + e[1], c = k + e[2];
      if (a < 0 || b < 0 || c < 0 || a >= n || b >= n || c >= n) continue;
      char& r = reached[(static_cast<std::size_t>(c) * n + b) * n + a];
      if (r || in(a, b, c) != in(i, j, k)) continue;
      r = 1;
      queue.push_back({a, b, c});
    }
  }
  return std::find(reached.begin(), reached.end(), 0) != reached.end();
}

/// classifyCell and hasHiddenComponent against the references, on every cell of
/// the given sizes in a block of random phases; returns how often each branch ran.
struct BranchCounts {
  int complexFaces = 0, uniformCells = 0, interior = 0, hidden = 0, visible = 0;
};
BranchCounts compareWithReferences(int blockSize, double insideFraction, std::initializer_list<int> sizes,
                                   unsigned seed) {
  std::mt19937 rng(seed);
  cell::MetaCellSamples s;
  s.allocate(blockSize, {0, 0, 0}, kOut);
  std::bernoulli_distribution speck(insideFraction);
  for (float& v : s.values) v = speck(rng) ? kIn : kOut;
  const SamplePhases phases = phasesOf(s);
  FaceLabeller labeller;
  BranchCounts counts;
  for (const int size : sizes)
    for (int z = 0; z + size <= blockSize; z += size)
      for (int y = 0; y + size <= blockSize; y += size)
        for (int x = 0; x + size <= blockSize; x += size) {
          const std::array<int, 3> o{x, y, z};
          const CellTopology got = classifyCell(phases, o, size, {}, labeller);
          const CellTopology want = referenceTopology(s, o, size);
          EXPECT_EQ(got.cornerSigns, want.cornerSigns) << size << " at " << x << ',' << y << ',' << z;
          EXPECT_EQ(got.complexEdges, want.complexEdges) << size << " at " << x << ',' << y << ',' << z;
          EXPECT_EQ(got.complexFaces, want.complexFaces) << size << " at " << x << ',' << y << ',' << z;
          EXPECT_EQ(got.boundaryUniform, want.boundaryUniform) << size << " at " << x << ',' << y << ',' << z;
          EXPECT_EQ(got.interiorComponent, want.interiorComponent) << size << " at " << x << ',' << y << ',' << z;
          const bool hidden = hasHiddenComponent(phases, o, size);
          EXPECT_EQ(hidden, size >= 2 && referenceHidden(s, o, size)) << size << " at " << x << ',' << y << ',' << z;
          counts.complexFaces += got.complexFaces != 0;
          counts.uniformCells += got.boundaryUniform && !got.interiorComponent;
          counts.interior += got.interiorComponent;
          (hidden ? counts.hidden : counts.visible) += size >= 2;
        }
  return counts;
}

TEST(Criteria, ClassificationMatchesTheDefinitionsOnRandomSamples) {
  // Sparse specks and dense noise at every cell size, so the one-phase
  // shortcut, the 3 x 3 faces and the bit-parallel floods all run.
  BranchCounts total;
  unsigned seed = 17;
  for (const double inside : {0.003, 0.01, 0.05, 0.5}) {
    const BranchCounts c = compareWithReferences(16, inside, {1, 2, 4, 8, 16}, seed++);
    total.complexFaces += c.complexFaces;
    total.uniformCells += c.uniformCells;
    total.interior += c.interior;
    total.hidden += c.hidden;
    total.visible += c.visible;
  }
  EXPECT_GT(total.complexFaces, 0);
  EXPECT_GT(total.uniformCells, 0);
  EXPECT_GT(total.interior, 0);
  EXPECT_GT(total.hidden, 0);
  EXPECT_GT(total.visible, 0);
}

TEST(Criteria, CellsWiderThanAWordMatchTheDefinitions) {
  // Faces and cells of more than 64 samples a side take the labelling and
  // byte-flood paths; a few specks make complex faces and hidden components.
  const BranchCounts c = compareWithReferences(128, 2e-5, {64, 128}, 3);
  EXPECT_GT(c.complexFaces + c.interior, 0);
  EXPECT_GT(c.hidden, 0);
}

}  // namespace
}  // namespace isovdb::octree
