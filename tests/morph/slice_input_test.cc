// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Slice images in: PNG and 1-bit BMP, filled regions and thin contours (holes
// by nesting), sizes padded, heights checked; the per-slice signed distance and
// the convex-hull centroid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "isovdb/errors.h"
#include "isovdb/morph/centring.h"
#include "isovdb/morph/contour_fill.h"
#include "isovdb/morph/slice_image.h"
#include "isovdb/morph/slice_sdf.h"
#include "isovdb/morph/slice_stack.h"
#include "morph_test_support.h"
#include "support/test_support.h"

namespace isovdb::morph::test {
namespace {

using isovdb::test::TempDir;
using isovdb::test::writeFile;

/// A 1-bit monochrome BMP (palette: 0 black, 1 white), bottom-up rows padded to 4 bytes.
std::string monochromeBmp(const Mask2& white) {
  const int rowBytes = ((white.width + 31) / 32) * 4;
  const int dataBytes = rowBytes * white.height, offset = 14 + 40 + 8;
  std::string b;
  auto u16 = [&](int v) {
    b += char(v & 255);
    b += char((v >> 8) & 255);
  };
  auto u32 = [&](int v) {
    u16(v & 0xffff);
    u16((v >> 16) & 0xffff);
  };
  b += "BM";
  u32(offset + dataBytes);
  u32(0);
  u32(offset);
  u32(40);
  u32(white.width);
  u32(white.height);
  u16(1);
  u16(1);
  u32(0);
  u32(dataBytes);
  u32(2835);
  u32(2835);
  u32(2);
  u32(0);
  u32(0x000000);
  u32(0xffffff);
  for (int y = white.height - 1; y >= 0; --y) {
    std::string row(rowBytes, '\0');
    for (int x = 0; x < white.width; ++x)
      if (white.at(x, y)) row[x / 8] = char(row[x / 8] | (0x80 >> (x % 8)));
    b += row;
  }
  return b;
}

TEST(ContourFill, ThinContoursNestAsHoles) {
  const Mask2 annulus = vase()[0];  // circle with a square hole
  EXPECT_EQ(fillContours(contourOf(annulus)).inside, annulus.inside);
  // A contour inside the hole is an island again.
  const Mask2 island = rectangle(64, 64, 29, 29, 35, 35);
  const Mask2 drawn = unite(contourOf(annulus), contourOf(island));
  EXPECT_EQ(fillContours(drawn).inside, unite(annulus, island).inside);
}

TEST(ContourFill, FilledRegionsKeepTheirHoles) {
  const Mask2 annulus = vase()[1];
  EXPECT_EQ(fillContours(annulus).inside, annulus.inside);
}

TEST(SliceImage, MonochromeBmpAndPngGiveTheSameSlice) {
  TempDir dir;
  const Mask2 shape = candlestick()[3];
  // Black drawing on white: the border decides which colour is the background.
  Mask2 white = shape;
  for (auto& v : white.inside) v = 1 - v;
  writeFile(dir / "a.bmp", monochromeBmp(white));
  writeSliceImage(dir / "b.png", shape);
  EXPECT_EQ(readSliceImage(dir / "a.bmp").inside, shape.inside);
  EXPECT_EQ(readSliceImage(dir / "b.png").inside, shape.inside);
}

TEST(SliceImage, CorruptImageNamesTheFile) {
  TempDir dir;
  writeFile(dir / "bad.png", "\x89PNG\r\n\x1a\n truncated");
  try {
    readSliceImage(dir / "bad.png");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad.png"), std::string::npos);
  }
}

// stb_image grows its buffers from what a PNG's data says (the fuzzer's damaged 8 x 8 PNG
// asked for 2 GB); io::checkPngData walks the chunks and inflates the data first.
TEST(SliceImage, PngDataIsBoundedByItsHeaderBeforeDecoding) {
  TempDir dir;
  writeSliceImage(dir / "ok.png", rectangle(40, 30, 5, 5, 20, 20));
  const std::string png = isovdb::test::readFile(dir / "ok.png");
  const auto message = [&](const std::string& bytes) {
    writeFile(dir / "bad.png", bytes);
    try {
      readSliceImage(dir / "bad.png");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("read");
  };
  EXPECT_EQ(message(png), "read");
  // IHDR (at byte 8) now declares 4 x 3 pixels: 3 rows of 1 + 4 bytes, where the data
  // inflates to 30 rows of 41 (stb_image does not check the chunks' CRC, nor do we).
  std::string small = png;
  small[16 + 3] = 4;
  small[20 + 3] = 3;
  EXPECT_NE(message(small).find("inflates to more than the 15 bytes its header declares"), std::string::npos)
      << message(small);
  // The first chunk's length past the end of the file.
  std::string longer = png;
  longer[8] = '\x7f';
  EXPECT_NE(message(longer).find("chunk 'IHDR' at byte 8 declares 2130706445 bytes, past the end of the file"),
            std::string::npos)
      << message(longer);
}

// stb_image decodes a BMP that declares width 0 (fuzz_slice_image: reading its border then
// indexed an empty mask).
TEST(SliceImage, ImageWithoutPixelsIsRefused) {
  TempDir dir;
  std::string bmp = monochromeBmp(rectangle(8, 8, 2, 2, 5, 5));
  for (int i = 0; i < 4; ++i) bmp[18 + i] = 0;  // biWidth
  writeFile(dir / "empty.bmp", bmp);
  try {
    readSliceImage(dir / "empty.bmp");
    FAIL() << "an image of width 0 was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("empty.bmp': the image has no pixels (0 x 8)"), std::string::npos) << e.what();
  }
}

// A top-down BMP stores its height negated; stb_image's header probe reports it so, and
// the size check passed 8 x -16,777,208 pixels as fewer than any limit (the fuzzer's
// slice_image harness: 134 M pixels decoded, then labelled for > 10 s).
TEST(SliceImage, TopDownBmpCountsItsPixelsAgainstTheLimit) {
  TempDir dir;
  std::string bmp = monochromeBmp(rectangle(8, 8, 2, 2, 5, 5));
  const std::int32_t height = -16777208;
  for (int i = 0; i < 4; ++i) bmp[22 + i] = static_cast<char>((static_cast<std::uint32_t>(height) >> (8 * i)) & 0xff);
  writeFile(dir / "tall.bmp", bmp);
  try {
    readSliceImage(dir / "tall.bmp", std::int64_t{1} << 20);
    FAIL() << "a declared 8 x 16777208 image was decoded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tall.bmp': the image declares 8 x 16777208 pixels"), std::string::npos)
        << e.what();
  }
}

TEST(SliceStack, NaturalOrderPaddingAndHeights) {
  TempDir dir;
  writeSliceImage(dir / "s10.png", rectangle(20, 10, 2, 2, 5, 5));
  writeSliceImage(dir / "s2.png", rectangle(8, 30, 1, 1, 3, 3));
  writeFile(dir / "notes.txt", "ignored");
  writeFile(dir / "h.txt", "0.5\n2.5 # comment\n");
  const SliceStack stack = loadSliceDirectory(dir.path(), {.heightsFile = dir / "h.txt"});
  ASSERT_EQ(stack.slices.size(), 2u);
  EXPECT_EQ(stack.width, 20);
  EXPECT_EQ(stack.height, 30);
  EXPECT_EQ(stack.slices[0].mask.area(), 9);   // s2 first
  EXPECT_EQ(stack.slices[1].mask.area(), 16);  // s10 second
  EXPECT_DOUBLE_EQ(stack.slices[1].height, 2.5);
  writeFile(dir / "h.txt", "0\n");
  EXPECT_THROW(loadSliceDirectory(dir.path(), {.heightsFile = dir / "h.txt"}), InputError);
  writeFile(dir / "h.txt", "3\n1\n");
  EXPECT_THROW(loadSliceDirectory(dir.path(), {.heightsFile = dir / "h.txt"}), InputError);
  EXPECT_THROW(loadSliceDirectory(dir.path(), {}), InputError);
}

TEST(SliceSdf, DiscDistancesWithinThreeQuartersOfAPixel) {
  const Mask2 d = disc(64, 64, 31.3, 30.6, 15);
  const Field2 sdf = signedDistance(d);
  double worst = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const double exact = std::hypot(x - 31.3, y - 30.6) - 15;
      if (std::abs(exact) < 8) worst = std::max(worst, std::abs(sdf.at(x, y) - exact));
      EXPECT_EQ(sdf.at(x, y) <= 0, d.at(x, y));
    }
  EXPECT_LT(worst, 0.75);  // pixel boundary up to half a pixel off the circle + first-order sweeping
}

TEST(Centring, HullCentroidOfShapes) {
  const auto c = hullCentroid(rectangle(64, 64, 10, 20, 29, 27));
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->x, 19.5, 1e-9);
  EXPECT_NEAR(c->y, 23.5, 1e-9);
  // Two discs share one hull: its centroid is between them.
  const auto two = hullCentroid(candlestick()[0]);
  EXPECT_NEAR(two->x, 32, 1e-9);
  EXPECT_NEAR(two->y, 32, 1e-9);
  EXPECT_FALSE(hullCentroid(Mask2::empty(8, 8)));
}

}  // namespace
}  // namespace isovdb::morph::test
