// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file input_flags.h
/// @brief The flags that say how to read an input volume, shared by every subcommand
///        (they map one to one onto pipeline::InputOptions).
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "isovdb/pipeline/load_volume.h"
#include "isovdb/volume/distance_field.h"
#include "seismic_flags.h"

namespace isovdb::cli {

struct InputFlags {
  std::vector<std::int64_t> dims;
  std::string type;
  bool bigEndian = false;
  std::vector<double> spacing;
  std::int64_t headerBytes = 0;
  std::optional<double> threshold;
  std::vector<double> labels;
  bool scalar = false;
  std::string grid;
  SeismicFlags seismic;

  /// Registers the flags on a subcommand (`prefix` distinguishes a second input).
  /// `rawSpacing` false leaves out --spacing (`morph` uses it for slice spacing).
  void add(CLI::App& command, bool rawSpacing = true);
  /// Builds the options; `path` is used in error messages.
  /// @throw InputError for an unknown --type or malformed values.
  pipeline::InputOptions toOptions(const std::string& path) const;
};

}  // namespace isovdb::cli
