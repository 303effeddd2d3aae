// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/contour/dmc_table.h: the generated Dual Marching Cubes
// table and Wenger's alternative groupings (2B-I / 3B-I); and voxel_dmc.h's
// reading of the same cells (joined faces, split faces, tube sectors).
#include "isovdb/cell/dmc_table.h"
#include "isovdb/contour/voxel_dmc.h"

#include <gtest/gtest.h>

#include <bit>

#include "isovdb/octree/morton.h"

namespace isovdb::contour {
namespace {

using octree::bipolarEdgeMask;
using octree::cellEdgeCorner;
using octree::cellFaceEdgeMask;

std::uint8_t corners(std::initializer_list<int> list) {
  unsigned c = 0;
  for (int i : list) c |= 1u << i;
  return static_cast<std::uint8_t>(c);
}

void expectConsistent(std::uint8_t config, const cell::DmcEntry& entry) {
  const std::uint16_t bipolar = bipolarEdgeMask(config);
  std::uint16_t all = 0;
  for (int g = 0; g < entry.vertexCount; ++g) {
    const std::uint16_t group = entry.groups[static_cast<std::size_t>(g)];
    EXPECT_EQ(all & group, 0) << "config " << int(config);           // disjoint
    EXPECT_GE(std::popcount(group), 3) << "config " << int(config);  // a patch cuts at least 3 edges
    // Each face holds 0 or 2 (or, doubled, 4) edges of a group: the group is a closed cycle.
    for (int f = 0; f < 6; ++f) EXPECT_EQ(std::popcount(unsigned(group & cellFaceEdgeMask(f))) % 2, 0);
    all = static_cast<std::uint16_t>(all | group);
  }
  EXPECT_EQ(all, bipolar) << "config " << int(config);
  for (int e = 0; e < 12; ++e) {
    const int g = entry.vertexOfEdge[static_cast<std::size_t>(e)];
    if ((bipolar >> e) & 1) {
      ASSERT_GE(g, 0);
      EXPECT_TRUE((entry.groups[static_cast<std::size_t>(g)] >> e) & 1);
    } else {
      EXPECT_EQ(g, -1);
    }
  }
}

TEST(DmcTable, EveryEntryPartitionsTheBipolarEdgesIntoCycles) {
  int vertices = 0, maxVertices = 0;
  for (int c = 0; c < 256; ++c) {
    const auto config = static_cast<std::uint8_t>(c);
    expectConsistent(config, cell::dmcEntry(config));
    expectConsistent(config, cell::dmcEntry(config, true));
    vertices += cell::dmcEntry(config).vertexCount;
    maxVertices = std::max<int>(maxVertices, cell::dmcEntry(config).vertexCount);
    EXPECT_EQ(cell::dmcEntry(config).vertexCount == 0, config == 0 || config == 255);
  }
  EXPECT_EQ(maxVertices, 4);
  EXPECT_EQ(cell::dmcEntry(corners({0, 3, 5, 6})).vertexCount, 4);  // four isolated inside corners
  // The generated table equals a copy built again from scratch.
  for (int c = 0; c < 256; ++c) {
    const cell::DmcEntry e = cell::detail::buildDmcEntry(static_cast<std::uint8_t>(c), 0);
    EXPECT_EQ(e.groups, cell::dmcEntry(static_cast<std::uint8_t>(c)).groups);
  }
  RecordProperty("vertices", vertices);
}

TEST(DmcTable, KnownCases) {
  // One inside corner: one triangle-like patch over its three edges.
  const cell::DmcEntry& one = cell::dmcEntry(corners({0}));
  ASSERT_EQ(one.vertexCount, 1);
  EXPECT_EQ(one.groups[0], bipolarEdgeMask(corners({0})));
  // Two inside corners on a face diagonal: inside corners are separated -> two vertices.
  EXPECT_EQ(cell::dmcEntry(corners({0, 3})).vertexCount, 2);
  EXPECT_EQ(cell::dmcEntry(corners({0, 3})).doubleFace, -1);
  // Two opposite corners of the cube: two vertices.
  EXPECT_EQ(cell::dmcEntry(corners({0, 7})).vertexCount, 2);
  // An edge of two inside corners: one quad-like patch of 4 edges.
  ASSERT_EQ(cell::dmcEntry(corners({0, 1})).vertexCount, 1);
  EXPECT_EQ(std::popcount(cell::dmcEntry(corners({0, 1})).groups[0]), 4);
  // 2B-I: two OUTSIDE corners on the diagonal of face z-min (face 4): one vertex over 6 edges,
  // passing twice through face 4; the alternative splits it into the two corners' triangles.
  const auto twoB = static_cast<std::uint8_t>(~corners({0, 3}));
  ASSERT_EQ(cell::dmcEntry(twoB).vertexCount, 1);
  EXPECT_EQ(cell::dmcEntry(twoB).doubleFace, 4);
  ASSERT_EQ(cell::dmcEntry(twoB, true).vertexCount, 2);
  EXPECT_EQ(std::popcount(cell::dmcEntry(twoB, true).groups[0]), 3);
  EXPECT_EQ(std::popcount(cell::dmcEntry(twoB, true).groups[1]), 3);
  // 3B-I: outside {0, 3, 7}: one vertex, alternative = a triangle + a quad.
  const auto threeB = static_cast<std::uint8_t>(~corners({0, 3, 7}));
  ASSERT_EQ(cell::dmcEntry(threeB).vertexCount, 1);
  EXPECT_EQ(cell::dmcEntry(threeB).doubleFace, 4);
  ASSERT_EQ(cell::dmcEntry(threeB, true).vertexCount, 2);
  EXPECT_EQ(
      std::popcount(cell::dmcEntry(threeB, true).groups[0]) + std::popcount(cell::dmcEntry(threeB, true).groups[1]), 7);
}

TEST(DmcTable, DoubledFacesAreExactlyWengers2BAnd3BConfigurations) {
  int twoB = 0, threeB = 0;
  for (int c = 0; c < 256; ++c) {
    const auto config = static_cast<std::uint8_t>(c);
    const cell::DmcEntry& base = cell::dmcEntry(config);
    const cell::DmcEntry& alt = cell::dmcEntry(config, true);
    if (base.doubleFace < 0) {
      EXPECT_EQ(alt.groups, base.groups);
      continue;
    }
    const int f = base.doubleFace;
    EXPECT_TRUE(cell::isAmbiguousFace(config, f));
    const int outside = 8 - std::popcount(unsigned(config));
    if (outside == 2) ++twoB;
    if (outside == 3) ++threeB;
    EXPECT_TRUE(outside == 2 || outside == 3) << c;
    // The alternative has one more vertex, and no group holds all four edges of face f.
    EXPECT_EQ(alt.vertexCount, base.vertexCount + 1);
    const std::uint16_t onFace = static_cast<std::uint16_t>(bipolarEdgeMask(config) & cellFaceEdgeMask(f));
    for (int g = 0; g < alt.vertexCount; ++g) EXPECT_NE(alt.groups[static_cast<std::size_t>(g)] & onFace, onFace);
  }
  // 6 faces x 2 diagonals: 1 configuration 2B and 2 configurations 3B each.
  EXPECT_EQ(twoB, 12);
  EXPECT_EQ(threeB, 24);
}

TEST(DmcTable, InsideOutsideDualityFlipsEveryAmbiguousFace) {
  // Resolving every face with the outside separated is the table of the complement.
  for (int c = 0; c < 256; ++c) {
    const auto config = static_cast<std::uint8_t>(c);
    const cell::DmcEntry flipped = cell::detail::buildDmcEntry(config, 0x3f);
    const cell::DmcEntry& complement = cell::dmcEntry(static_cast<std::uint8_t>(~config));
    EXPECT_EQ(flipped.vertexCount, complement.vertexCount) << c;
    EXPECT_EQ(flipped.groups, complement.groups) << c;
  }
}

TEST(DmcTable, FaceDecisionDependsOnlyOnTheFace) {
  // The pairing of a face's bipolar edges is the same for every configuration
  // that agrees on that face's corners (so both cells of a face agree).
  for (int f = 0; f < 6; ++f)
    for (int c = 0; c < 256; ++c) {
      const auto config = static_cast<std::uint8_t>(c);
      if (!cell::isAmbiguousFace(config, f)) continue;
      const cell::DmcEntry& e = cell::dmcEntry(config);
      if (e.doubleFace == f) continue;
      // Edges of face f grouped in pairs: each pair shares an inside corner.
      const std::uint16_t onFace = static_cast<std::uint16_t>(bipolarEdgeMask(config) & cellFaceEdgeMask(f));
      for (int g = 0; g < e.vertexCount; ++g) {
        const unsigned pair = e.groups[static_cast<std::size_t>(g)] & onFace;
        if (pair == 0) continue;
        ASSERT_EQ(std::popcount(pair), 2);
        const int a = std::countr_zero(pair), b = std::countr_zero(pair & (pair - 1));
        int shared = -1;
        for (int ea = 0; ea < 2; ++ea)
          for (int eb = 0; eb < 2; ++eb)
            if (cellEdgeCorner(a, ea) == cellEdgeCorner(b, eb)) shared = cellEdgeCorner(a, ea);
        ASSERT_GE(shared, 0);
        EXPECT_TRUE((config >> shared) & 1) << "config " << c << " face " << f;
      }
    }
}

TEST(VoxelDmc, JoinedFacesAreTheComplementsTableAndEveryEntryIsConsistent) {
  for (int c = 0; c < 256; ++c) {
    const auto config = static_cast<std::uint8_t>(c);
    const cell::DmcEntry& voxels = voxelDmcEntry(config);
    expectConsistent(config, voxels);
    EXPECT_EQ(voxels.groups, cell::dmcEntry(static_cast<std::uint8_t>(~config)).groups) << c;
    // The doubled face of the joined reading is the complement's: outside corners on its diagonal.
    EXPECT_EQ(voxels.doubleFace, cell::dmcEntry(static_cast<std::uint8_t>(~config)).doubleFace) << c;
  }
}

TEST(VoxelDmc, TubesAreTheFourBodyDiagonalPairsAndTheirSectorsCutEveryEdge) {
  int tubes = 0;
  for (int c = 0; c < 256; ++c) {
    const auto config = static_cast<std::uint8_t>(c);
    if (!isTubeConfig(config)) {
      EXPECT_EQ(voxelCellVertexCount(config), voxelDmcEntry(config).vertexCount) << c;
      continue;
    }
    ++tubes;
    EXPECT_EQ(std::popcount(static_cast<unsigned>(config)), 2);
    EXPECT_EQ(voxelCellVertexCount(config), 3);
    EXPECT_EQ(voxelDmcEntry(config).vertexCount, 2) << "two caps without the tube";
    const TubeSectors& t = tubeSectors(config);
    const std::uint16_t bipolar = bipolarEdgeMask(config);
    std::array<int, 3> faces{};
    for (int f = 0; f < 6; ++f) {
      const int k = t.sectorOfFace[static_cast<std::size_t>(f)];
      ASSERT_GE(k, 0);
      ASSERT_LT(k, 3);
      ++faces[static_cast<std::size_t>(k)];
      // The sector holds the face's two bipolar edges.
      const std::uint16_t onFace = static_cast<std::uint16_t>(bipolar & cellFaceEdgeMask(f));
      EXPECT_EQ(std::popcount(static_cast<unsigned>(onFace)), 2);
      EXPECT_EQ(t.edges[static_cast<std::size_t>(k)] & onFace, onFace);
    }
    EXPECT_EQ(faces, (std::array<int, 3>{2, 2, 2}));
    // Every bipolar edge separates two sectors (it is in exactly two), and a sector
    // touches both inside corners (one face at each).
    for (int e = 0; e < 12; ++e) {
      int in = 0;
      for (const std::uint16_t edges : t.edges) in += (edges >> e) & 1;
      EXPECT_EQ(in, ((bipolar >> e) & 1) ? 2 : 0) << "config " << c << " edge " << e;
    }
    const int a = std::countr_zero(static_cast<unsigned>(config));
    for (int k = 0; k < 3; ++k) {
      int nearA = 0;
      for (int f = 0; f < 6; ++f)
        if (t.sectorOfFace[static_cast<std::size_t>(f)] == k && ((a >> (f >> 1)) & 1) == (f & 1)) ++nearA;
      EXPECT_EQ(nearA, 1) << "config " << c << " sector " << k;
    }
  }
  EXPECT_EQ(tubes, 4);
}

TEST(VoxelDmc, SplitVerticesTakeTheTwoEdgesAtEachOutsideCorner) {
  // Corners 0 and 3 inside on face z = 0 (an ambiguous face), corners 1 and 2 outside.
  const std::uint8_t config = corners({0, 3, 4, 5, 6, 7});
  ASSERT_TRUE(cell::isAmbiguousFace(config, 4));
  const auto edges = splitVertexEdges(config, 4);
  for (int slot = 0; slot < 2; ++slot) {
    const int outside = slot == 0 ? 1 : 2;
    const unsigned pair = edges[static_cast<std::size_t>(slot)];
    ASSERT_EQ(std::popcount(pair), 2);
    for (int e = 0; e < 12; ++e)
      if ((pair >> e) & 1) {
        EXPECT_TRUE((cellFaceEdgeMask(4) >> e) & 1);
        EXPECT_TRUE(cellEdgeCorner(e, 0) == outside || cellEdgeCorner(e, 1) == outside);
      }
  }
}

}  // namespace
}  // namespace isovdb::contour
