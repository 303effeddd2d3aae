// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace isovdb::test {

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "isovdb-test-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::filesystem::path dataDir() { return ISOVDB_DATA_DIR; }
std::filesystem::path sharedDataDir() { return ISOVDB_SHARED_DATA_DIR; }
std::filesystem::path cliPath() { return ISOVDB_CLI; }

void writeFile(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int runCommand(const std::string& command, std::string* output) {
  const std::string full = command + " 2>&1";
  FILE* pipe = ::popen(full.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buffer;
  std::string text;
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) text.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  if (output) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

CliRun runCli(const std::string& arguments) {
  CliRun run;
  run.status = runCommand(cliPath().string() + " --quiet " + arguments, &run.output);
  return run;
}

void expectCleanFailure(const CliRun& run, const std::vector<std::string>& fragments, const TempDir& outDir) {
  EXPECT_NE(run.status, 0) << run.output;
  EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
  EXPECT_EQ(run.output.rfind("isovdb: error: ", 0), 0u) << run.output;
  for (const std::string& fragment : fragments)
    EXPECT_NE(run.output.find(fragment), std::string::npos) << "missing '" << fragment << "' in: " << run.output;
  EXPECT_TRUE(std::filesystem::is_empty(outDir.path())) << "output left behind";
}

}  // namespace isovdb::test
