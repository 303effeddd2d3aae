// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file union_find.h
/// @brief The root of a union-find forest over a vertex's few incident triangles (the
///        validator's umbrella test, splitPinchedVertices' fans).
#pragma once

#include <cstdint>
#include <vector>

namespace isovdb::mesh {

/// The root of `x` in `parent` (parent[r] == r at a root), halving the path on the way.
inline std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

}  // namespace isovdb::mesh
