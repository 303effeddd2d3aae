// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file shapes.h
/// @brief Analytic solids sampled at voxel centres: synthetic binary volumes of
///        known topology for tests and benchmarks (sphere, torus, genus-2,
///        gyroid slab, salt-dome-like body), and a surface-heavy benchmark
///        volume of random ellipsoids (blobs) whose voxel count is counted.
///
/// Coordinates: voxel index space, voxel (i, j, k) sampled at its centre, the
/// integer point (i, j, k), as in OpenVDB. Every shape is defined once in
/// normalised coordinates q = (2 (x + 0.5) - n) / size (the cube of `size`
/// voxels maps to [-1, 1]^3) and therefore exists at any resolution: the
/// volume at 64^3 and at 1024^3 hold the same solid. The smallest feature
/// (tube, wall, gap, tunnel) is at least ~5 voxels wide at size 64.
///
/// Each shape comes with the Euler characteristic of the continuous solid,
/// chi = components - handles + cavities; with the (26, 6) digital topology of
/// volume/digital_topology.h the sampled volume has the same chi for every
/// size >= 64 (tested at 64 and 128).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>

#include "isovdb/io/slice_stream.h"

namespace isovdb::samples {

enum class ShapeKind {
  Sphere,      ///< ball of radius 0.8 (chi = 1)
  Torus,       ///< solid torus, major radius 0.6, minor 0.25, axis z (chi = 0)
  Genus2,      ///< two solid tori fused side by side (chi = -1)
  GyroidSlab,  ///< one labyrinth of a gyroid clipped to a flat box (chi = -6, numerical)
  SaltDome,    ///< mushroom-shaped salt body with a tunnel plus two detached pods (chi = 2)
  Blobs,       ///< thousands of random overlapping ellipsoids from a seed (chi not known in closed form)
};

/// Options shared by every shape.
struct ShapeOptions {
  /// Edge of the sampled cube in voxels: dims are size^3, except the gyroid
  /// slab which is size x size x (5 size / 8). Range 16..16384; features are
  /// resolvable (several voxels wide) from 64 up.
  int size = 128;
  /// Sample value of inside voxels in generated slices (outside is 0); 1..255,
  /// e.g. 255 for viewers that expect full-intensity masks.
  std::uint8_t label = 1;
  /// Seed of the random bodies of ShapeKind::Blobs (other shapes ignore it).
  std::uint64_t seed = 1;
};

/// All shapes, in declaration order.
std::span<const ShapeKind> allShapes();
/// The shapes whose Euler characteristic is known (all but Blobs): the topology tests' inputs.
std::span<const ShapeKind> shapesOfKnownTopology();
/// Canonical lower-case name: "sphere", "torus", "genus2", "gyroid-slab", "salt-dome".
std::string_view shapeName(ShapeKind kind);
/// One-line description of the construction (for `isovdb-sample --list`).
std::string_view shapeDescription(ShapeKind kind);
/// Parses a canonical name (also accepts '_' for '-'); std::nullopt when unknown.
std::optional<ShapeKind> parseShape(std::string_view name);
/// Euler characteristic of the continuous solid (components - handles + cavities).
/// @throw InputError for Blobs (a random union: count it with volume::eulerCharacteristic).
int knownEulerCharacteristic(ShapeKind kind);

/// Samples along x, y, z of the volume of `kind` at `options.size`.
/// @throw InputError when options are out of range.
std::array<std::int64_t, 3> shapeDims(ShapeKind kind, const ShapeOptions& options);

/// True iff index-space point (x, y, z) lies inside the solid (voxel (i, j, k)
/// is inside iff inside(kind, options, i, j, k)). Points outside the volume
/// are outside. Deterministic; agrees exactly with generateSlice().
/// @throw InputError when options are out of range.
bool inside(ShapeKind kind, const ShapeOptions& options, double x, double y, double z);

/// Writes slice z (0 <= z < dims[2]) of the sampled volume into `out`
/// (dims[0] * dims[1] bytes, x fastest): options.label inside, 0 outside.
/// Rows are computed in parallel (TBB); the result does not depend on scheduling.
/// @throw InputError when options or z are out of range.
void generateSlice(ShapeKind kind, const ShapeOptions& options, std::int64_t z, std::uint8_t* out);

/// A SliceStream that generates the volume on the fly: header with dims from
/// shapeDims(), uint8 samples, unit spacing, zero origin; source() is
/// "sample:<name>@<size>". Memory: one byte slice.
/// @throw InputError when options are out of range.
std::unique_ptr<io::SliceStream> makeShapeStream(ShapeKind kind, const ShapeOptions& options);

}  // namespace isovdb::samples
