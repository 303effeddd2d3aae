// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file morph_test_support.h
/// @brief Slices built in code (rectangles, discs, annuli; paper 002's synthetic
///        cases) and the mesh cross-section used to check that a reconstruction
///        reproduces its original slices.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "isovdb/mesh/mesh.h"
#include "isovdb/morph/plane.h"
#include "isovdb/morph/slice_stack.h"

namespace isovdb::morph::test {

/// Pixels whose centre is in the axis-aligned rectangle [x0, x1] × [y0, y1].
Mask2 rectangle(int w, int h, double x0, double y0, double x1, double y1);
/// Pixels whose centre is within `r` of (cx, cy).
Mask2 disc(int w, int h, double cx, double cy, double r);
Mask2 unite(const Mask2& a, const Mask2& b);
Mask2 subtract(const Mask2& a, const Mask2& b);
/// Thin 8-connected contours of a mask: inside pixels with an outside 4-neighbour.
Mask2 contourOf(const Mask2& mask);

/// A stack from masks at heights (pixel size 1, z step 1).
SliceStack stackOf(const std::vector<Mask2>& masks, const std::vector<double>& heights);

/// Paper 002's synthetic cases on 64 × 64 slices, 8 pixels apart.
std::vector<Mask2> pyramid();
std::vector<Mask2> candlestick();
std::vector<Mask2> vase();

/// Writes masks as slice_<i>.png into `dir` (contours only when `asContours`).
void writeStack(const std::filesystem::path& dir, const std::vector<Mask2>& masks, bool asContours = false);

/// Inside of a closed mesh (world = pixel units) at height z, sampled at pixel
/// centres by scanline parity on the plane's cut through the triangles.
Mask2 crossSection(const mesh::Mesh& mesh, double z, int w, int h);

/// |a Δ b| / |b|.
double symmetricDifference(const Mask2& a, const Mask2& b);

}  // namespace isovdb::morph::test
