// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file checked_extract.h
/// @brief `isovdb extract ARGUMENTS --check` in a temporary directory, its figures
///        (the `--stats` JSON) returned: the CLI tests that assert a mesh's
///        guarantees on real files read them from here.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "support/test_support.h"

namespace isovdb::test {

/// Runs the extraction with `--check` (exit status 0 expected: the check passed) and
/// returns its statistics, "check" among them.
inline nlohmann::json checkedExtract(const std::string& arguments) {
  const TempDir dir;
  const auto stats = dir / "stats.json";
  std::string output;
  EXPECT_EQ(runCommand(cliPath().string() + " -q extract " + arguments + " --check -o " + (dir / "m.ply").string() +
                           " --stats " + stats.string(),
                       &output),
            0)
      << arguments << ": " << output;
  return nlohmann::json::parse(readFile(stats));
}

}  // namespace isovdb::test
