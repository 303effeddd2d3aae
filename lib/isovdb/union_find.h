// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file union_find.h
/// @brief The root of an element of a union-find forest kept as a parent array: the one
///        find of the validator's umbrella test and splitPinchedVertices' fans (mesh/), DMC's
///        edge groups (cell/), the octree's phase components (octree/criteria) and the
///        reservoir's loops and pinched pillars. Uniting stays with each caller: which root
///        joins which (the lowest index, or any) is each caller's own rule.
#pragma once

#include <cstddef>

namespace isovdb {

/// The root of `x` in `parent` (parent[r] == r at a root: a std::vector or std::array of
/// indices), halving the path on the way. The roots do not depend on the halving, only
/// on how the caller united them.
template <typename Parents>
constexpr typename Parents::value_type findRoot(Parents& parent, typename Parents::value_type x) noexcept {
  using Index = typename Parents::value_type;
  while (parent[static_cast<std::size_t>(x)] != x) {
    const Index up = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    parent[static_cast<std::size_t>(x)] = up;
    x = up;
  }
  return x;
}

}  // namespace isovdb
