/// @file test_support.h
/// @brief Small helpers shared by the test suites.
#pragma once

#include <filesystem>
#include <string>

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

}  // namespace isovdb::test
