// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file extract_settings.h
/// @brief The one table of `isovdb extract`'s settings: each a CLI flag `--name` and a
///        Python keyword `name` (dashes as underscores), with its help text and its
///        default taken from ExtractOptions. The CLI registers its flags from it, the
///        Python module builds `extract()`'s signature from it, and a test checks the
///        type stub and the documentation against it, so no name or default can drift.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "isovdb/pipeline/extract.h"

namespace isovdb::pipeline {

/// What a user chose: the options, with the enum-valued settings as their names
/// until resolve() checks them.
struct ExtractChoices {
  ExtractOptions options;
  std::string method = std::string(contourMethodName(ExtractOptions{}.contour.method));
  std::string topology = "auto";  ///< auto | voxels | mdmc
  std::string boundary = std::string(boundaryModeName(ExtractOptions{}.boundary));
  std::string distance = std::string(volume::distanceMethodName(ExtractOptions{}.distance.method));
  std::string inside = std::string(nameOf(kScalarInsideNames, ExtractOptions{}.scalarInside));

  /// The options with the named settings parsed.
  /// @param keywords true: messages name Python keywords (`method`), false: CLI flags (`--method`).
  /// @throw InputError naming the setting and the accepted values.
  ExtractOptions resolve(bool keywords = false) const;
};

/// What a user chose for the distance field of a mask (`isovdb sdf`, Python distance_field()).
struct DistanceChoices {
  volume::DistanceFieldOptions options;
  std::string method = std::string(volume::distanceMethodName(volume::DistanceFieldOptions{}.method));

  /// @throw InputError naming the setting (flag or keyword) and the accepted values.
  volume::DistanceFieldOptions resolve(bool keywords = false) const;
};

/// One setting, bound to a field of an ExtractChoices or a DistanceChoices.
struct Setting {
  std::string_view name;  ///< CLI `--name`; Python `name` with '-' -> '_'
  std::string_view help;
  /// An optional number is unset by default (CLI: flag not given; Python: None).
  std::variant<int*, float*, double*, bool*, std::string*, std::optional<float>*> value;
  /// For a bool that defaults to true: the CLI flag that turns it off (`--no-name`).
  bool negatable = false;
};

/// Every setting of `choices`, in the order the CLI lists them and Python takes them.
std::vector<Setting> extractSettings(ExtractChoices& choices);
/// The distance-field settings (a part of extract's), bound to `options` and to
/// `method`, the method's name.
std::vector<Setting> distanceSettings(volume::DistanceFieldOptions& options, std::string& method);
inline std::vector<Setting> distanceSettings(DistanceChoices& choices) {
  return distanceSettings(choices.options, choices.method);
}

/// The Python keyword of a setting: dashes as underscores.
std::string keywordOf(std::string_view name);

}  // namespace isovdb::pipeline
