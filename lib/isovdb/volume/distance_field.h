// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file distance_field.h
/// @brief Binary mask → narrow-band signed distance field (paper 000 §4.1), with OpenVDB tools.
///
/// Binary voxels carry no sub-voxel position: contouring them directly gives
/// staircases. The distance field puts the surface half-way between inside and
/// outside voxel centres and smooths nothing away: no morphological closing is
/// applied by default, so the topology of the mask is kept.
#pragma once

#include <optional>
#include <string_view>

#include "isovdb/named_values.h"
#include "isovdb/progress.h"
#include "isovdb/volume/volume.h"

namespace isovdb::volume {

/// How the band of a mask is computed.
enum class DistanceMethod {
  /// From the mask's interface (volume/interface_band.h): sub-voxel distances at the
  /// interface voxels from the mask blurred by a small Gaussian, extended to the band
  /// along the nearest interface voxel's tangent plane. Signs are exactly the mask's.
  Interface,
  /// OpenVDB's topologyToLevelSet (PDE renormalisation by LevelSetTracker), then
  /// (redistance) one fast-sweeping pass, tools::sdfToSdf. 5-10x slower; kept for comparison.
  Tracker,
};

inline constexpr NameTable<DistanceMethod, 2> kDistanceMethodNames{
    {{DistanceMethod::Interface, "interface"}, {DistanceMethod::Tracker, "tracker"}}};
constexpr std::string_view distanceMethodName(DistanceMethod method) { return nameOf(kDistanceMethodNames, method); }
/// The method named `name`; std::nullopt for another name.
constexpr std::optional<DistanceMethod> parseDistanceMethod(std::string_view name) {
  return valueNamed(kDistanceMethodNames, name);
}

struct DistanceFieldOptions {
  DistanceMethod method = DistanceMethod::Interface;
  /// Half-width of the narrow band, in voxels. Contouring needs at least 2;
  /// larger bands cost memory proportional to the width.
  int halfWidth = 3;
  /// Morphological closing steps before the distance transform. 0 keeps the
  /// mask's topology; >0 fills gaps of that many voxels (changes topology).
  int closingSteps = 0;
  /// Tracker only: re-solve the Eikonal equation in the band by fast sweeping
  /// (tools::sdfToSdf) after OpenVDB's topologyToLevelSet: distances within 0.4
  /// voxel of exact instead of 1.3 on a sphere, for about twice the time.
  bool redistance = true;
  /// The band is computed chunk by chunk (cubes of this many voxels, a multiple
  /// of 8, each from the mask around it plus a halo), so the transient memory is
  /// that of one chunk per thread, not of the whole band: Interface, about 22
  /// bytes per voxel of (chunk + 16)^3 (11 MiB at 64); Tracker, about 40 MiB at
  /// 128 (OpenVDB's tools). 0: Tracker on the whole grid at once (faster on small
  /// volumes, 3-5x the band's memory at peak); Interface at 64. The Interface
  /// band does not depend on the chunk size, bit for bit.
  int chunkSize = 64;
};

/// @throw InputError naming the option that is out of range.
void checkDistanceFieldOptions(const DistanceFieldOptions& options);

/// Signed distance to the boundary of the mask, in voxels, NEGATIVE inside.
/// Voxels farther than halfWidth are inactive with value ±halfWidth (their sign
/// is still right). Memory: O(surface · halfWidth) for the result plus one chunk
/// in flight per TBB thread (chunks run in parallel). The result does not depend on chunkSize (to float rounding).
/// @pre `mask.kind() == VolumeKind::Mask`
/// @throw InputError for another kind; Interrupted on cancellation.
Volume distanceField(const Volume& mask, const DistanceFieldOptions& options = {}, Interrupter* interrupter = nullptr);

/// The voxels of a distance field strictly below `iso` (its interior, tiles kept),
/// as a mask volume with the same geometry.
/// @pre `sdf.kind() == VolumeKind::DistanceField`
Volume interiorMask(const Volume& sdf, double iso = 0.0);

}  // namespace isovdb::volume
