// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file setting_flags.h
/// @brief Registers a table of pipeline::Setting as CLI flags: the flags of
///        `extract`, `octree`, `sdf` and `morph` come from the table Python's
///        keywords are made from, so their names, defaults and help cannot differ.
#pragma once

#include <CLI/CLI.hpp>

#include <vector>

#include "isovdb/pipeline/extract_settings.h"

namespace isovdb::cli {

/// `--name VALUE` for each setting (its current value shown as the default); a bool
/// is `--name`, or `--no-name` when it is negatable (on by default).
void addSettingFlags(CLI::App& command, const std::vector<pipeline::Setting>& settings);

}  // namespace isovdb::cli
