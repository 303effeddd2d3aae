// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests of lib/isovdb/mesh/preview.h: the picture shows the object's silhouette,
// in front-face colours for an outward mesh and back-face colours for an inside-out one.
#include "isovdb/mesh/preview.h"

#include <gtest/gtest.h>

#include <cmath>

#include "isovdb/errors.h"

namespace isovdb::mesh {
namespace {

/// A closed octahedron of radius r at the origin, counter-clockwise seen from outside.
Mesh octahedron(float r) {
  Mesh m;
  m.positions = {{r, 0, 0}, {-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {0, 0, -r}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

struct Pixel {
  int r, g, b;
  bool background() const { return r == kPreviewBackground && g == kPreviewBackground && b == kPreviewBackground; }
};

Pixel at(const PreviewImage& image, int x, int y) {
  const std::size_t i =
      3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x));
  return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

TEST(Preview, ShowsTheSilhouetteInFrontFaceColours) {
  const PreviewImage image = renderPreview(octahedron(3.0f), {.width = 200, .height = 160});
  ASSERT_EQ(image.rgb.size(), 200u * 160u * 3u);
  std::size_t object = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) object += !at(image, x, y).background();
  // Fitted into the picture: a good part of it, the corners left empty.
  EXPECT_GT(object, 200u * 160u / 5);
  EXPECT_LT(object, 200u * 160u * 9 / 10);
  for (const auto& [x, y] : {std::pair{0, 0}, {199, 0}, {0, 159}, {199, 159}})
    EXPECT_TRUE(at(image, x, y).background());
  const Pixel centre = at(image, 100, 80);
  EXPECT_FALSE(centre.background());
  EXPECT_LT(std::abs(centre.r - centre.g), 60) << "front faces are bone-coloured";
}

TEST(Preview, InsideOutFacesAreRed) {
  Mesh m = octahedron(3.0f);
  for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  const Pixel centre = at(renderPreview(m, {.width = 200, .height = 160}), 100, 80);
  EXPECT_GT(centre.r, centre.g + 60) << "back faces are red";
}

TEST(Preview, EmptyMeshIsBackgroundAndSizesAreChecked) {
  const PreviewImage image = renderPreview(Mesh{}, {.width = 32, .height = 16});
  for (const std::uint8_t c : image.rgb) ASSERT_EQ(c, kPreviewBackground);
  EXPECT_THROW(renderPreview(Mesh{}, {.width = 8, .height = 600}), InputError);
}

}  // namespace
}  // namespace isovdb::mesh
