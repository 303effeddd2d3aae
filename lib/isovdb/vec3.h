// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file vec3.h
/// @brief The 3-vectors every stage exchanges: plain arrays (no arithmetic; the
///        algorithms that compute with them map them onto Eigen or OpenVDB types).
#pragma once

#include <array>

namespace isovdb {

using Vec3f = std::array<float, 3>;
using Vec3d = std::array<double, 3>;

}  // namespace isovdb
