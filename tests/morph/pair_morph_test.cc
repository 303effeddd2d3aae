// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/morph/pair_morph.h on pairs where paper 002's recipe has no
// good answer as written: a component that appears, and an empty slice.
#include "isovdb/morph/pair_morph.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "isovdb/morph/slice_sdf.h"
#include "morph/morph_test_support.h"

namespace isovdb::morph {
namespace {

using test::disc;
using test::unite;

/// Pixels of a canvas-sized field that are inside (value <= 0).
std::int64_t insideArea(const Field2& f) {
  std::int64_t n = 0;
  for (float v : f.values) n += v <= 0.0f;
  return n;
}

/// Inside pixels of `f` within `r` of (cx, cy).
std::int64_t insideNear(const Field2& f, double cx, double cy, double r) {
  std::int64_t n = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) n += f.at(x, y) <= 0.0f && std::hypot(x - cx, y - cy) <= r;
  return n;
}

TEST(PairMorph, CentringFollowsATranslationButNotAComponentThatAppears) {
  const std::vector<double> half{0.5};
  // A disc that moves: centring carries it along (paper 002 §3.3.2).
  const Mask2 left = disc(96, 64, 24, 32, 9), right = disc(96, 64, 40, 32, 9);
  const PairResult moved = morphPair(left, right, signedDistance(left), signedDistance(right), half, PairOptions{});
  EXPECT_TRUE(moved.stats.centred);
  EXPECT_GT(insideNear(moved.slices[0], 32, 32, 6), 100) << "the mid slice is the disc half-way";
  // A second disc appears far away: the hull centroid jumps by 24 pixels, and
  // centring would drag the first disc half of that. It stays where it is.
  const Mask2 two = unite(left, disc(96, 64, 72, 32, 9));
  const PairResult appeared = morphPair(left, two, signedDistance(left), signedDistance(two), half, PairOptions{});
  EXPECT_FALSE(appeared.stats.centred);
  EXPECT_GT(insideNear(appeared.slices[0], 24, 32, 6), 100) << "the first disc stays in place";
}

TEST(PairMorph, AStructureEndingBetweenTwoSlicesTapersToASeed) {
  // The level-set equation only moves the levels φ has; an empty slice's field
  // has no zero level, so a morph started from it would leave every plane empty.
  const Mask2 empty = Mask2::empty(64, 64), blob = disc(64, 64, 30.4, 33.2, 14);
  const std::vector<double> fractions{0.25, 0.5, 0.75};
  for (const bool emptyFirst : {true, false}) {
    const Mask2& a = emptyFirst ? empty : blob;
    const Mask2& b = emptyFirst ? blob : empty;
    const PairResult r = morphPair(a, b, signedDistance(a), signedDistance(b), fractions, PairOptions{});
    ASSERT_EQ(r.slices.size(), 3u);
    std::vector<std::int64_t> areas;
    for (const Field2& f : r.slices) areas.push_back(insideArea(f));
    if (!emptyFirst) std::reverse(areas.begin(), areas.end());  // nearer the blob = larger
    EXPECT_GT(areas[0], 0) << "a quarter of the way from the empty slice the section is there";
    EXPECT_LT(areas[0], areas[1]);
    EXPECT_LT(areas[1], areas[2]);
    EXPECT_LT(areas[2], blob.area());
    EXPECT_GT(insideNear(r.slices[1], 30.4, 33.2, 14), areas[1] * 9 / 10) << "it grows where the blob is";
  }
}

}  // namespace
}  // namespace isovdb::morph
