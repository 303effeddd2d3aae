// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/octree/morton.h and the lookups of linear_octree.h,
// randomized against a naive pointer octree.
#include "isovdb/octree/morton.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <vector>

#include "isovdb/octree/linear_octree.h"

namespace isovdb::octree {
namespace {

TEST(Morton, RootChildParentAndDepth) {
  EXPECT_EQ(keyDepth(kRootKey), 0);
  EXPECT_EQ(childKey(kRootKey, 5), 0b1101u);
  EXPECT_EQ(childKey(97, 3), 0b1100001011u);  // paper 000, section 3.4.2
  EXPECT_EQ(parentKey(0b1100001011u), 97u);
  EXPECT_EQ(keyDepth(childKey(childKey(kRootKey, 7), 0)), 2);
  EXPECT_EQ(octantOf(childKey(97, 6)), 6);
  EXPECT_EQ(encodeKey(1, {1, 0, 1}), childKey(kRootKey, 5));
  static_assert(encodeKey(2, {3, 0, 0}) == 0b1001001u);
}

// Every cell at every depth up to 128^3 cells per side: exhaustive up to depth 4,
// random beyond (depth 7 = 1-voxel cells of a 128 meta-cell).
TEST(Morton, EncodeDecodeNeighbourRoundTripEveryLevel) {
  std::mt19937 rng(42);
  for (int depth = 0; depth <= 8; ++depth) {
    const int n = 1 << depth;
    std::vector<std::array<int, 3>> cells;
    if (depth <= 4) {
      for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
          for (int x = 0; x < n; ++x) cells.push_back({x, y, z});
    } else {
      std::uniform_int_distribution<int> u(0, n - 1);
      for (int i = 0; i < 20000; ++i) cells.push_back({u(rng), u(rng), u(rng)});
      cells.push_back({0, 0, 0});
      cells.push_back({n - 1, n - 1, n - 1});
    }
    for (const auto& c : cells) {
      const MortonKey key = encodeKey(depth, c);
      ASSERT_EQ(keyDepth(key), depth);
      const KeyCoord d = decodeKey(key);
      ASSERT_EQ(d.depth, depth);
      ASSERT_EQ(d.xyz, c);
      if (depth > 0) {
        ASSERT_EQ(parentKey(key), encodeKey(depth - 1, {c[0] / 2, c[1] / 2, c[2] / 2}));
        ASSERT_EQ(childKey(parentKey(key), octantOf(key)), key);
        ASSERT_EQ(octantOf(key), (c[0] & 1) | (c[1] & 1) << 1 | (c[2] & 1) << 2);
      }
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const std::array<int, 3> m{c[0] + dx, c[1] + dy, c[2] + dz};
            const bool inside = m[0] >= 0 && m[1] >= 0 && m[2] >= 0 && m[0] < n && m[1] < n && m[2] < n;
            const MortonKey nk = neighbourKey(key, dx, dy, dz);
            ASSERT_EQ(nk, inside ? encodeKey(depth, m) : kInvalidKey) << depth << " " << dx << dy << dz;
            if (inside) {
              ASSERT_EQ(neighbourKey(nk, -dx, -dy, -dz), key);
            }
          }
    }
  }
}

TEST(Morton, CellEdgeAndFaceTables) {
  for (int e = 0; e < 12; ++e) {
    const int c0 = cellEdgeCorner(e, 0), c1 = cellEdgeCorner(e, 1);
    EXPECT_EQ(c0 ^ c1, 1 << cellEdgeAxis(e));
    EXPECT_EQ(cellEdgeIndex(cellEdgeAxis(e), c0), e);
  }
  for (int f = 0; f < 6; ++f) EXPECT_EQ(std::popcount(cellFaceEdgeMask(f)), 4);
  EXPECT_EQ(bipolarEdgeMask(0x00), 0);
  EXPECT_EQ(bipolarEdgeMask(0xff), 0);
  EXPECT_EQ(std::popcount(bipolarEdgeMask(0x01)), 3);
}

// A naive pointer octree: random subdivision, then point location and face
// adjacency by brute force, compared with the linear octree.
struct Node {
  std::array<int, 3> origin{};
  int size = 0;
  MortonKey key = kRootKey;
  std::array<std::unique_ptr<Node>, 8> children;
  bool leaf() const { return !children[0]; }
};

void subdivideRandomly(Node& node, int depth, int maxDepth, std::mt19937& rng) {
  std::bernoulli_distribution split(depth == 0 ? 1.0 : 0.45);
  if (depth >= maxDepth || !split(rng)) return;
  const int h = node.size / 2;
  for (int o = 0; o < 8; ++o) {
    auto child = std::make_unique<Node>();
    child->size = h;
    child->origin = {node.origin[0] + (o & 1) * h, node.origin[1] + ((o >> 1) & 1) * h,
                     node.origin[2] + ((o >> 2) & 1) * h};
    child->key = childKey(node.key, o);
    subdivideRandomly(*child, depth + 1, maxDepth, rng);
    node.children[static_cast<std::size_t>(o)] = std::move(child);
  }
}

void collectLeaves(const Node& node, std::vector<const Node*>& out) {
  if (node.leaf()) {
    out.push_back(&node);
    return;
  }
  for (const auto& c : node.children) collectLeaves(*c, out);
}

const Node* locate(const Node& node, std::array<int, 3> voxel) {
  if (node.leaf()) return &node;
  const int h = node.size / 2;
  const int o =
      (voxel[0] >= node.origin[0] + h) | (voxel[1] >= node.origin[1] + h) << 1 | (voxel[2] >= node.origin[2] + h) << 2;
  return locate(*node.children[static_cast<std::size_t>(o)], voxel);
}

TEST(LinearOctree, RandomizedAgainstPointerOctree) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 12; ++trial) {
    const int size = 64;
    Node root;
    root.size = size;
    subdivideRandomly(root, 0, 6, rng);
    std::vector<const Node*> naive;
    collectLeaves(root, naive);
    std::vector<OctreeLeaf> leaves;
    for (const Node* n : naive) {
      OctreeLeaf l;
      l.key = n->key;
      l.origin = n->origin;
      l.size = n->size;
      l.depth = static_cast<std::uint8_t>(keyDepth(n->key));
      leaves.push_back(l);
    }
    std::shuffle(leaves.begin(), leaves.end(), rng);
    const LinearOctree tree(size, {0, 0, 0}, std::move(leaves));
    ASSERT_EQ(tree.leafCount(), naive.size());
    // Keys and origins agree (pointer geometry vs key decoding).
    for (const OctreeLeaf& l : tree.leaves()) {
      EXPECT_EQ(tree.cellOrigin(l.key), l.origin);
      EXPECT_EQ(tree.cellSize(l.key), l.size);
      EXPECT_EQ(tree.findLeaf(l.key), &l - tree.leaves().data());
    }
    // Point location.
    std::uniform_int_distribution<int> u(0, size - 1);
    for (int i = 0; i < 3000; ++i) {
      const std::array<int, 3> v{u(rng), u(rng), u(rng)};
      const std::int64_t j = tree.findLeafContainingVoxel(v);
      ASSERT_NE(j, LinearOctree::kNone);
      EXPECT_EQ(tree.leaf(static_cast<std::size_t>(j)).key, locate(root, v)->key);
      const std::array<float, 3> p{v[0] + 0.5f, v[1] + 0.25f, v[2] + 0.75f};
      EXPECT_EQ(tree.findLeafContaining(p), j);
      // A finest-depth key is contained by the same leaf.
      EXPECT_EQ(tree.findLeafContaining(encodeKey(tree.finestDepth(), v)), j);
    }
    // Face neighbours against brute force (shared face area > 0).
    std::vector<std::size_t> across;
    for (std::size_t i = 0; i < tree.leafCount(); i += 3) {
      const OctreeLeaf& a = tree.leaf(i);
      for (int f = 0; f < 6; ++f) {
        tree.leavesAcrossFace(i, f, across);
        std::vector<std::size_t> expected;
        const int axis = f >> 1;
        const int plane = (f & 1) ? a.origin[axis] + a.size : a.origin[axis];
        for (std::size_t j = 0; j < tree.leafCount(); ++j) {
          const OctreeLeaf& b = tree.leaf(j);
          const bool onPlane = (f & 1) ? b.origin[axis] == plane : b.origin[axis] + b.size == plane;
          bool overlap = onPlane;
          for (int t = 0; t < 3 && overlap; ++t)
            if (t != axis) overlap = b.origin[t] < a.origin[t] + a.size && a.origin[t] < b.origin[t] + b.size;
          if (overlap) expected.push_back(j);
        }
        EXPECT_EQ(across, expected) << "leaf " << i << " face " << f;
      }
    }
    // The leaves around unit edges: each entry contains the adjacent voxel.
    for (int i = 0; i < 500; ++i) {
      const std::array<int, 3> s{u(rng), u(rng), u(rng)};
      const int axis = i % 3;
      const auto around = tree.leavesAroundEdge(s, axis);
      const auto uv = otherAxes(axis);
      for (int q = 0; q < 4; ++q) {
        std::array<int, 3> v = s;
        v[uv[0]] += (q & 1) - 1;
        v[uv[1]] += ((q >> 1) & 1) - 1;
        const bool in = v[uv[0]] >= 0 && v[uv[1]] >= 0;
        if (!in) {
          EXPECT_EQ(around[static_cast<std::size_t>(q)], LinearOctree::kNone);
        } else {
          EXPECT_EQ(tree.leaf(static_cast<std::size_t>(around[static_cast<std::size_t>(q)])).key, locate(root, v)->key);
        }
      }
    }
  }
}

}  // namespace
}  // namespace isovdb::octree
