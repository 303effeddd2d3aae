/// @file seismic_flags.h
/// @brief The input flags of SEG-Y amplitude cubes (and of amplitude-like scalars):
///        header byte positions, the dead band, and the two binary masks.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "isovdb/pipeline/load_volume.h"

namespace isovdb::cli {

struct SeismicFlags {
  bool segy = false;
  int inlineByte = 189;
  int crosslineByte = 193;
  float clip = 0.f;
  std::string mask;
  std::vector<double> maskRange;

  void add(CLI::App& command);
  /// Completes the options InputFlags built: SEG-Y reading (by flag or extension),
  /// the amplitude field by default for SEG-Y, the clip, and --mask/--mask-range.
  /// @param[in] otherMask true when --threshold or --labels chose a mask.
  /// @throw InputError for malformed or contradicting flags (names the flag).
  void apply(const std::string& path, bool otherMask, pipeline::InputOptions& options) const;
};

}  // namespace isovdb::cli
