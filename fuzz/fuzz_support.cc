// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "fuzz_support.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <system_error>

namespace isovdb::fuzz {

namespace {

/// This process's scratch folder, made on first use and removed at exit.
const std::filesystem::path& scratchFolder() {
  static const std::filesystem::path folder = [] {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() / ("isovdb-fuzz-" + std::to_string(static_cast<long>(getpid())));
    std::filesystem::create_directories(path);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(scratchFolder(), ignored);
    });
    return path;
  }();
  return folder;
}

}  // namespace

std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size, std::string_view extension) {
  std::filesystem::path path = scratchFolder() / ("input" + std::string(extension));
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::perror(path.c_str());
    std::abort();  // the harness cannot run at all: not the reader's fault, but never silent
  }
  return path;
}

}  // namespace isovdb::fuzz

/// LeakSanitizer's built-in suppressions for the harnesses. OpenVDB 10's
/// RootNode::readTopology allocates a child node and reads its topology before the
/// node is in the root's table, so a corrupt tree that throws there leaks that node
/// (OpenVDB's own exception safety; the vdb harness found it in its first seconds).
/// The CLI exits on the error; a long-lived Python process loses one node per bad file.
extern "C" const char* __lsan_default_suppressions() {  // NOLINT(readability-identifier-naming)
  return "leak:openvdb::*::tree::RootNode<*>::readTopology\n";
}
