// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file input_choices.h
/// @brief How a front end's input choices (CLI flags, Python keyword arguments) become
///        InputOptions, so both resolve them the same way: SEG-Y by flag or extension,
///        the amplitude field by default for SEG-Y, the clip, and the mask rules.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "isovdb/pipeline/load_volume.h"

namespace isovdb::pipeline {

/// What a user said about an input, one field per CLI flag / Python keyword.
struct InputChoices {
  std::optional<io::RawOptions> raw;               ///< --dims/--type/...: a headerless raw file
  std::optional<double> threshold;                 ///< --threshold T: mask, inside = value > T
  std::vector<double> labels;                      ///< --labels: mask, inside = value is one of these
  bool scalar = false;                             ///< --scalar: contour the samples directly
  std::string grid;                                ///< --grid: .vdb grid name
  bool segy = false;                               ///< --segy: SEG-Y whatever the extension
  io::SegyOptions segyBytes;                       ///< --inline-byte, --crossline-byte
  float clip = 0.f;                                ///< --clip: scalars, |value| < clip inactive
  std::string mask;                                ///< --mask "above A" | "below A"
  std::optional<std::array<double, 2>> maskRange;  ///< --mask-range LO,HI
};

/// Resolves the choices for `path`: SEG-Y reading (flag or .sgy/.segy), the mask rule
/// (--threshold, --labels, --mask or --mask-range; default value > 0), and the field
/// kind (a mask unless --scalar, or SEG-Y without any mask choice).
/// @throw InputError for contradicting or malformed choices (names the flag).
InputOptions resolveInputChoices(const std::filesystem::path& path, const InputChoices& choices);

}  // namespace isovdb::pipeline
