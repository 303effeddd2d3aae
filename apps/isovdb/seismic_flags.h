// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file seismic_flags.h
/// @brief The input flags of SEG-Y amplitude cubes (and of amplitude-like scalars):
///        header byte positions, the dead band, and the two binary masks.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "isovdb/pipeline/input_choices.h"

namespace isovdb::cli {

struct SeismicFlags {
  bool segy = false;
  int inlineByte = 189;
  int crosslineByte = 193;
  float clip = 0.f;
  std::string mask;
  std::vector<double> maskRange;

  void add(CLI::App& command);
  /// Copies these flags into the choices InputFlags gathers (pipeline::resolveInputChoices
  /// checks and resolves them).
  void fill(pipeline::InputChoices& choices) const;
};

}  // namespace isovdb::cli
