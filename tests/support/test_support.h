// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file test_support.h
/// @brief Small helpers shared by the test suites.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace isovdb::test {

/// A fresh directory under the system temp dir, removed with its contents on destruction.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

/// The repository's data/ folder.
std::filesystem::path dataDir();
/// ../shared/data beside the repository (real sample data with provenance).
std::filesystem::path sharedDataDir();
/// Path of the built `isovdb` command-line tool.
std::filesystem::path cliPath();

/// Writes `bytes` to `path` (test input files).
void writeFile(const std::filesystem::path& path, const std::string& bytes);
/// Reads a whole file.
std::string readFile(const std::filesystem::path& path);

/// Runs a shell command, returns its exit status; stdout+stderr go to `output`.
int runCommand(const std::string& command, std::string* output = nullptr);

/// Exit status and combined output of one run of the `isovdb` binary.
struct CliRun {
  int status = 0;
  std::string output;
};

/// Runs `isovdb --quiet ARGUMENTS`.
CliRun runCli(const std::string& arguments);

/// Asserts the failure contract of the CLI: non-zero exit, one line on stderr
/// starting "isovdb: error: " that contains every fragment, and nothing written
/// in `outDir`.
void expectCleanFailure(const CliRun& run, const std::vector<std::string>& fragments, const TempDir& outDir);

}  // namespace isovdb::test
