// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Tests for data/generators/shapes.h: every sample shape's digital Euler
// characteristic (stream and BoolGrid paths of volume/digital_topology.h)
// equals its known value at two resolutions; streams are deterministic.
#include "generators/shapes.h"

#include <array>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <openvdb/openvdb.h>

#include "isovdb/errors.h"
#include "isovdb/volume/digital_topology.h"
#include "isovdb/volume/grids.h"

namespace isovdb::samples {
namespace {

/// The mask volume of a shape, built voxel by voxel with an accessor from
/// the generated slices (independent of the ingest code).
volume::Volume shapeMask(ShapeKind kind, const ShapeOptions& options) {
  const auto dims = shapeDims(kind, options);
  auto grid = openvdb::BoolGrid::create(false);
  auto accessor = grid->getAccessor();
  std::vector<std::uint8_t> slice(static_cast<std::size_t>(dims[0] * dims[1]));
  for (std::int64_t z = 0; z < dims[2]; ++z) {
    generateSlice(kind, options, z, slice.data());
    for (std::int64_t y = 0; y < dims[1]; ++y)
      for (std::int64_t x = 0; x < dims[0]; ++x)
        if (slice[static_cast<std::size_t>(y * dims[0] + x)])
          accessor.setValueOn(openvdb::Coord(static_cast<int>(x), static_cast<int>(y), static_cast<int>(z)), true);
  }
  return volume::Volume(volume::VolumeKind::Mask, grid, volume::Geometry{}, std::string(shapeName(kind)));
}

/// Dense copy of a (small) shape volume, padded by one background voxel.
struct PaddedVolume {
  std::array<std::int64_t, 3> dims;
  std::vector<std::uint8_t> inside;
  std::int64_t index(std::int64_t x, std::int64_t y, std::int64_t z) const { return (z * dims[1] + y) * dims[0] + x; }
};

PaddedVolume paddedVolume(ShapeKind kind, const ShapeOptions& options) {
  const auto shape = shapeDims(kind, options);
  PaddedVolume volume{{shape[0] + 2, shape[1] + 2, shape[2] + 2}, {}};
  volume.inside.assign(static_cast<std::size_t>(volume.dims[0] * volume.dims[1] * volume.dims[2]), 0);
  std::vector<std::uint8_t> slice(static_cast<std::size_t>(shape[0] * shape[1]));
  for (std::int64_t z = 0; z < shape[2]; ++z) {
    generateSlice(kind, options, z, slice.data());
    for (std::int64_t y = 0; y < shape[1]; ++y)
      for (std::int64_t x = 0; x < shape[0]; ++x)
        volume.inside[static_cast<std::size_t>(volume.index(x + 1, y + 1, z + 1))] =
            slice[static_cast<std::size_t>(y * shape[0] + x)] != 0;
  }
  return volume;
}

/// Connected components of voxels with inside == `foreground`: 26-adjacency
/// for the foreground, 6-adjacency for the background.
int countComponents(const PaddedVolume& volume, bool foreground) {
  std::vector<std::uint8_t> seen(volume.inside.size(), 0);
  int components = 0;
  const auto& d = volume.dims;
  for (std::int64_t start = 0; start < static_cast<std::int64_t>(volume.inside.size()); ++start) {
    if (seen[start] || (volume.inside[start] != 0) != foreground) continue;
    ++components;
    std::deque<std::int64_t> queue{start};
    seen[start] = 1;
    while (!queue.empty()) {
      const std::int64_t at = queue.front();
      queue.pop_front();
      const std::int64_t x = at % d[0], y = (at / d[0]) % d[1], z = at / (d[0] * d[1]);
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int steps = (dx != 0) + (dy != 0) + (dz != 0);
            if (steps == 0 || (!foreground && steps > 1)) continue;
            const std::int64_t nx = x + dx, ny = y + dy, nz = z + dz;
            if (nx < 0 || ny < 0 || nz < 0 || nx >= d[0] || ny >= d[1] || nz >= d[2]) continue;
            const std::int64_t next = volume.index(nx, ny, nz);
            if (seen[next] || (volume.inside[next] != 0) != foreground) continue;
            seen[next] = 1;
            queue.push_back(next);
          }
    }
  }
  return components;
}

class ShapeTopology : public ::testing::TestWithParam<std::tuple<ShapeKind, int>> {};

TEST_P(ShapeTopology, DigitalEulerCharacteristicMatchesKnownValue) {
  const auto [kind, size] = GetParam();
  const ShapeOptions options{.size = size};
  auto stream = makeShapeStream(kind, options);
  EXPECT_EQ(volume::eulerCharacteristic(*stream, volume::MaskRule{}), knownEulerCharacteristic(kind));
  EXPECT_EQ(volume::eulerCharacteristic(shapeMask(kind, options)), knownEulerCharacteristic(kind));
}

INSTANTIATE_TEST_SUITE_P(AllShapes, ShapeTopology,
                         ::testing::Combine(::testing::Values(ShapeKind::Sphere, ShapeKind::Torus, ShapeKind::Genus2,
                                                              ShapeKind::GyroidSlab, ShapeKind::SaltDome),
                                            ::testing::Values(64, 128)),
                         [](const auto& info) {
                           std::string name(shapeName(std::get<0>(info.param)));
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name + "_" + std::to_string(std::get<1>(info.param));
                         });

TEST(Shapes, ComponentsAndCavitiesExplainChi) {
  // chi = components - handles + cavities; counting components and cavities
  // pins down the handles, so e.g. the salt dome's chi = 2 really is
  // 3 pieces with one tunnel (and not 2 pieces without one).
  struct Expected {
    ShapeKind kind;
    int components, handles, cavities;
  };
  for (const Expected& expected : {Expected{ShapeKind::Sphere, 1, 0, 0}, Expected{ShapeKind::Torus, 1, 1, 0},
                                   Expected{ShapeKind::Genus2, 1, 2, 0}, Expected{ShapeKind::SaltDome, 3, 1, 0}}) {
    SCOPED_TRACE(std::string(shapeName(expected.kind)));
    const PaddedVolume volume = paddedVolume(expected.kind, ShapeOptions{.size = 64});
    const int components = countComponents(volume, true);
    const int cavities = countComponents(volume, false) - 1;
    EXPECT_EQ(components, expected.components);
    EXPECT_EQ(cavities, expected.cavities);
    EXPECT_EQ(components - expected.handles + cavities, knownEulerCharacteristic(expected.kind));
  }
}

TEST(Shapes, NamesRoundTrip) {
  ASSERT_EQ(allShapes().size(), 6u);
  ASSERT_EQ(shapesOfKnownTopology().size(), 5u);
  for (ShapeKind kind : allShapes()) {
    EXPECT_EQ(parseShape(shapeName(kind)), kind);
    EXPECT_FALSE(shapeDescription(kind).empty());
  }
  EXPECT_EQ(parseShape("gyroid_slab"), ShapeKind::GyroidSlab);
  EXPECT_EQ(parseShape("Salt-Dome"), ShapeKind::SaltDome);
  EXPECT_EQ(parseShape("cube"), std::nullopt);
  EXPECT_EQ(knownEulerCharacteristic(ShapeKind::Sphere), 1);
  EXPECT_EQ(knownEulerCharacteristic(ShapeKind::Torus), 0);
  EXPECT_EQ(knownEulerCharacteristic(ShapeKind::Genus2), -1);
  EXPECT_EQ(knownEulerCharacteristic(ShapeKind::SaltDome), 2);
}

TEST(Shapes, StreamHeader) {
  auto stream = makeShapeStream(ShapeKind::Torus, ShapeOptions{.size = 40});
  const io::VolumeHeader& header = stream->header();
  EXPECT_EQ(header.dims, (std::array<std::int64_t, 3>{40, 40, 40}));
  EXPECT_EQ(header.sampleType, io::SampleType::UInt8);
  EXPECT_EQ(header.spacing, (std::array<double, 3>{1.0, 1.0, 1.0}));
  EXPECT_EQ(header.origin, (std::array<double, 3>{0.0, 0.0, 0.0}));
  EXPECT_EQ(stream->source(), "sample:torus@40");
  EXPECT_EQ(stream->nextSlice(), 0);

  auto slab = makeShapeStream(ShapeKind::GyroidSlab, ShapeOptions{.size = 64});
  EXPECT_EQ(slab->header().dims, (std::array<std::int64_t, 3>{64, 64, 40}));
}

TEST(Shapes, StreamIsDeterministicAndMatchesInside) {
  for (ShapeKind kind : allShapes()) {
    SCOPED_TRACE(std::string(shapeName(kind)));
    const ShapeOptions options{.size = 48, .label = 255};
    auto first = makeShapeStream(kind, options);
    auto second = makeShapeStream(kind, options);
    const auto dims = first->header().dims;
    std::vector<float> a(static_cast<std::size_t>(dims[0] * dims[1])), b(a.size());
    std::int64_t insideCount = 0;
    for (std::int64_t z = 0; z < dims[2]; ++z) {
      first->readSlice(a.data());
      second->readSlice(b.data());
      EXPECT_EQ(first->nextSlice(), z + 1);
      ASSERT_EQ(a, b) << "slice " << z;
      for (std::int64_t y = 0; y < dims[1]; ++y)
        for (std::int64_t x = 0; x < dims[0]; ++x) {
          const float value = a[static_cast<std::size_t>(y * dims[0] + x)];
          ASSERT_TRUE(value == 0.f || value == 255.f);
          ASSERT_EQ(value != 0.f,
                    inside(kind, options, static_cast<double>(x), static_cast<double>(y), static_cast<double>(z)))
              << x << " " << y << " " << z;
          insideCount += value != 0.f;
        }
    }
    EXPECT_GT(insideCount, 0);
    EXPECT_THROW(first->readSlice(a.data()), InputError);  // past the last slice
  }
}

TEST(Shapes, SameSolidAtEveryResolution) {
  // The fraction of the cube inside the sphere is ~4/3 pi 0.4^3 at any size.
  for (int size : {64, 128}) {
    const ShapeOptions options{.size = size};
    std::vector<std::uint8_t> slice(static_cast<std::size_t>(size * size));
    std::int64_t count = 0;
    for (int z = 0; z < size; ++z) {
      generateSlice(ShapeKind::Sphere, options, z, slice.data());
      for (std::uint8_t value : slice) count += value;
    }
    const double fraction = static_cast<double>(count) / (double(size) * size * size);
    EXPECT_NEAR(fraction, 4.0 / 3.0 * 3.14159265358979 * 0.064, 0.01) << size;
  }
  EXPECT_FALSE(inside(ShapeKind::Sphere, ShapeOptions{.size = 64}, -5.0, 32.0, 32.0));
  EXPECT_TRUE(inside(ShapeKind::Sphere, ShapeOptions{.size = 64}, 31.5, 31.5, 31.5));
}

TEST(Shapes, RejectsBadOptions) {
  EXPECT_THROW(makeShapeStream(ShapeKind::Sphere, ShapeOptions{.size = 8}), InputError);
  EXPECT_THROW(makeShapeStream(ShapeKind::Sphere, ShapeOptions{.size = 64, .label = 0}), InputError);
  std::vector<std::uint8_t> slice(64 * 64);
  EXPECT_THROW(generateSlice(ShapeKind::Sphere, ShapeOptions{.size = 64}, 64, slice.data()), InputError);
}

}  // namespace
}  // namespace isovdb::samples
