// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file reconstruction_report.h
/// @brief The slice-morph front ends' shared vocabulary: the names of the
///        interpolation and progress modes, and the figures of a reconstruction
///        (what `isovdb morph --stats` and Python's morph_slices report).
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string_view>

#include "isovdb/morph/reconstruct.h"
#include "isovdb/named_values.h"

namespace isovdb::morph {

inline constexpr NameTable<Interpolation, 3> kInterpolationNames{
    {{Interpolation::LevelSet, "levelset"}, {Interpolation::Nearest, "nearest"}, {Interpolation::Linear, "linear"}}};
constexpr std::optional<Interpolation> parseInterpolation(std::string_view name) {
  return valueNamed(kInterpolationNames, name);
}
constexpr std::string_view interpolationName(Interpolation interpolation) {
  return nameOf(kInterpolationNames, interpolation);
}

inline constexpr NameTable<Progress, 3> kProgressNames{
    {{Progress::Exponential, "exponential"}, {Progress::Arrival, "arrival"}, {Progress::Iterations, "iterations"}}};
constexpr std::optional<Progress> parseProgress(std::string_view name) { return valueNamed(kProgressNames, name); }
constexpr std::string_view progressName(Progress progress) { return nameOf(kProgressNames, progress); }

/// @brief Checks what the options' front ends cannot: particles need the level-set
///        interpolation, a positive tolerance, at least one iteration.
/// @throw InputError naming the flag (`pls`, `tolerance`, `max-iterations`).
void checkReconstructOptions(const ReconstructOptions& options);

/// @brief The figures of `r`: modes, slices, iterations, per-pair figures, time
///        per intermediate slice and per iteration; and the stage timings under
///        "timings_s" (slice_sdf, morph, assembly).
nlohmann::ordered_json reconstructionReport(const Reconstruction& r, const ReconstructOptions& options);

}  // namespace isovdb::morph
