// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file volume_bindings.h
/// @brief Reading helpers shared by read_volume and read_segy.
#pragma once

#include <filesystem>

#include "bindings.h"
#include "isovdb/pipeline/input_choices.h"

namespace isovdb::python {

/// The mask and SEG-Y keywords read_volume and read_segy share (None: not given).
struct InputKeywords {
  py::object threshold, labels, mask, maskRange;
  float clip = 0.f;
  int inlineByte = 189, crosslineByte = 193;

  pipeline::InputChoices choices() const;
};

/// loadVolume with the GIL released and `progress` (a callable or None) as interrupter.
PyVolume loadWithProgress(const std::filesystem::path& path, const pipeline::InputOptions& options,
                          const py::object& progress);

}  // namespace isovdb::python
