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
