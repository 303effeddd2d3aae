// Tests of lib/isovdb/morph/pair_morph.h: when the pair is centred.
#include "isovdb/morph/pair_morph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "isovdb/morph/slice_sdf.h"
#include "morph/morph_test_support.h"

namespace isovdb::morph {
namespace {

using test::disc;
using test::unite;

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

}  // namespace
}  // namespace isovdb::morph
