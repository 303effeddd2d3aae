// Tests of lib/isovdb/octree/criteria.h on hand-built voxel faces.
#include "isovdb/octree/criteria.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace isovdb::octree {
namespace {

constexpr float kOut = 1.0f;
constexpr float kIn = -1.0f;

/// A 16^3 block all outside; the cell under test is (0,0,0) with side 8, and
/// its bottom face (z = 0, face index 4) is painted by the tests.
MetaCellSamples outsideBlock() {
  MetaCellSamples s;
  s.allocate(16, {0, 0, 0}, kOut);
  return s;
}

constexpr int kBottomFace = 4;  // 2 * axis(z) + side(min)

TEST(Criteria, CountSignChanges) {
  MetaCellSamples s = outsideBlock();
  EXPECT_EQ(countSignChanges(s, {0, 0, 0}, 0, 8, 0.0f), 0);
  s.value(8, 0, 0) = kIn;
  EXPECT_EQ(countSignChanges(s, {0, 0, 0}, 0, 8, 0.0f), 1);
  s.value(8, 0, 0) = 0.0f;  // exactly iso counts as inside
  EXPECT_EQ(countSignChanges(s, {0, 0, 0}, 0, 8, 0.0f), 1);
  EXPECT_FALSE(isComplexEdge(s, {0, 0, 0}, 0, 8, 0.0f));
}

TEST(Criteria, EdgeCrossedThreeTimesIsComplex) {
  MetaCellSamples s = outsideBlock();
  // Along the x edge at y = z = 0: out out in in out out in in in -> 3 changes.
  for (int x : {2, 3, 6, 7, 8}) s.value(x, 0, 0) = kIn;
  EXPECT_EQ(countSignChanges(s, {0, 0, 0}, 0, 8, 0.0f), 3);
  EXPECT_TRUE(isComplexEdge(s, {0, 0, 0}, 0, 8, 0.0f));
  FaceLabeller labeller;
  const CellTopology t = classifyCell(s, {0, 0, 0}, 8, {}, labeller);
  EXPECT_EQ(t.complexEdges, 1u << cellEdgeIndex(0, 0));
  EXPECT_TRUE(t.isComplex());
  EXPECT_TRUE(t.isHeterogeneous());
  EXPECT_EQ(t.cornerSigns, 1u << 1);  // corner (8,0,0) inside
}

TEST(Criteria, IsolatedIslandMakesAComplexFace) {
  MetaCellSamples s = outsideBlock();
  for (int y = 3; y <= 4; ++y)
    for (int x = 3; x <= 5; ++x) s.value(x, y, 0) = kIn;
  FaceLabeller labeller;
  const FaceLabeller::Result r = labeller.label(s, {0, 0, 0}, 2, 8, 0.0f);
  EXPECT_TRUE(r.isolatedComponent);
  EXPECT_FALSE(r.uniform);
  EXPECT_EQ(r.components, 2);
  const CellTopology t = classifyCell(s, {0, 0, 0}, 8, {}, labeller);
  EXPECT_EQ(t.complexEdges, 0);
  EXPECT_EQ(t.complexFaces, 1u << kBottomFace);
  EXPECT_TRUE(t.isComplex());
  EXPECT_EQ(t.cornerSigns, 0);  // invisible from the corners and the edges
  // The same island touching an edge is no longer isolated.
  for (int x = 0; x <= 3; ++x) s.value(x, 3, 0) = kIn;
  EXPECT_FALSE(labeller.label(s, {0, 0, 0}, 2, 8, 0.0f).isolatedComponent);
}

/// Paints a square ring (Chebyshev radius 2) centred at (cx, cy) on face z = 0.
void paintRing(MetaCellSamples& s, int cx, int cy) {
  for (int y = cy - 2; y <= cy + 2; ++y)
    for (int x = cx - 2; x <= cx + 2; ++x)
      if (std::max(std::abs(x - cx), std::abs(y - cy)) == 2) s.value(x, y, 0) = kIn;
}

TEST(Criteria, RingTouchingOneEdgeHasAComplexEdge) {
  // Ring x in [0, 4], y in [2, 6]: it lies along the edge x = 0 (y axis) in
  // the middle of it, so that edge changes sign twice; its hole is isolated.
  MetaCellSamples s = outsideBlock();
  paintRing(s, 2, 4);
  EXPECT_EQ(countSignChanges(s, {0, 0, 0}, 1, 8, 0.0f), 2);
  FaceLabeller labeller;
  EXPECT_TRUE(labeller.label(s, {0, 0, 0}, 2, 8, 0.0f).isolatedComponent);  // the hole
  const CellTopology t = classifyCell(s, {0, 0, 0}, 8, {}, labeller);
  EXPECT_EQ(t.complexEdges, 1u << cellEdgeIndex(1, 0));
  EXPECT_EQ(t.complexFaces, 0);  // a face with a complex edge is not a "complex face"
  EXPECT_FALSE(t.facesEvaluated);
  EXPECT_TRUE(t.isComplex());
}

TEST(Criteria, RingTouchingEdgesOnceHasAComplexFaceThroughItsHole) {
  // Ring x, y in [0, 4] around the corner: each of the two edges it touches
  // changes sign once (no complex edge), but the hole is an isolated outside
  // component, a closed contour loop that the edges cannot see.
  MetaCellSamples s = outsideBlock();
  paintRing(s, 2, 2);
  EXPECT_EQ(countSignChanges(s, {0, 0, 0}, 0, 8, 0.0f), 1);
  EXPECT_EQ(countSignChanges(s, {0, 0, 0}, 1, 8, 0.0f), 1);
  FaceLabeller labeller;
  const CellTopology t = classifyCell(s, {0, 0, 0}, 8, {}, labeller);
  EXPECT_EQ(t.complexEdges, 0);
  EXPECT_EQ(t.complexFaces, 1u << kBottomFace);
  EXPECT_TRUE(t.isComplex());
  // Filling the hole removes the complexity: one component touching two edges.
  for (int y = 1; y <= 3; ++y)
    for (int x = 1; x <= 3; ++x) s.value(x, y, 0) = kIn;
  const CellTopology filled = classifyCell(s, {0, 0, 0}, 8, {}, labeller);
  EXPECT_FALSE(filled.isComplex());
  EXPECT_TRUE(filled.isHeterogeneous());
}

TEST(Criteria, InteriorBlobIsDetectedOnlyWhenAsked) {
  MetaCellSamples s = outsideBlock();
  s.value(4, 4, 4) = kIn;
  FaceLabeller labeller;
  const CellTopology with = classifyCell(s, {0, 0, 0}, 8, {.iso = 0.0f, .detectInteriorComponents = true}, labeller);
  EXPECT_TRUE(with.boundaryUniform);
  EXPECT_TRUE(with.interiorComponent);
  EXPECT_TRUE(with.isComplex());
  const CellTopology without =
      classifyCell(s, {0, 0, 0}, 8, {.iso = 0.0f, .detectInteriorComponents = false}, labeller);
  EXPECT_FALSE(without.isComplex());
  EXPECT_FALSE(without.isHeterogeneous());
}

TEST(Criteria, BubbleInACellCrossedByTheSurfaceIsHidden) {
  // A plane crosses the 8-cell (its faces are not one phase, so classifyCell does not
  // look inside); a 1-voxel outside bubble below it touches no face.
  MetaCellSamples s = makeMetaCellSamples(16, {0, 0, 0}, [](int, int, int z) { return z - 5.5f; });
  FaceLabeller labeller;
  const CellTopology plane = classifyCell(s, {0, 0, 0}, 8, {}, labeller);
  EXPECT_FALSE(plane.isComplex());
  EXPECT_FALSE(plane.boundaryUniform);
  EXPECT_FALSE(hasHiddenComponent(s, {0, 0, 0}, 8, 0.0f));
  s.value(3, 4, 2) = 1.0f;  // outside, inside the inside half
  EXPECT_FALSE(classifyCell(s, {0, 0, 0}, 8, {}, labeller).isComplex()) << "the face criteria cannot see it";
  EXPECT_TRUE(hasHiddenComponent(s, {0, 0, 0}, 8, 0.0f));
  // On a face it is the face criteria's business, not hidden.
  s.value(3, 4, 2) = -2.5f;
  s.value(0, 4, 2) = 1.0f;
  EXPECT_FALSE(hasHiddenComponent(s, {0, 0, 0}, 8, 0.0f));
  // An inside speck in the outside half.
  s.value(4, 4, 7) = -1.0f;
  EXPECT_TRUE(hasHiddenComponent(s, {0, 0, 0}, 8, 0.0f));
  EXPECT_FALSE(hasHiddenComponent(s, {0, 0, 0}, 1, 0.0f));
}

TEST(Criteria, UniformCellIsSimpleAndHomogeneous) {
  const MetaCellSamples s = outsideBlock();
  FaceLabeller labeller;
  const CellTopology t = classifyCell(s, {8, 8, 8}, 8, {}, labeller);
  EXPECT_FALSE(t.isComplex());
  EXPECT_FALSE(t.isHeterogeneous());
  EXPECT_EQ(t.cornerSigns, 0);
}

}  // namespace
}  // namespace isovdb::octree
