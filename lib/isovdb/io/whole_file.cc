// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/whole_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>

#include "isovdb/errors.h"

namespace isovdb::io {

std::string readWholeFile(const std::filesystem::path& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) throw IoError("cannot read '" + path.string() + "': " + std::strerror(errno));
  std::error_code ec;
  const std::uintmax_t expected = std::filesystem::file_size(path, ec);
  std::string data(ec ? 0 : static_cast<std::size_t>(expected), '\0');
  data.resize(std::fread(data.data(), 1, data.size(), f.get()));
  char buffer[1 << 16];
  while (!std::ferror(f.get()) && !std::feof(f.get())) {
    const std::size_t n = std::fread(buffer, 1, sizeof buffer, f.get());
    data.append(buffer, n);
  }
  if (std::ferror(f.get())) throw IoError("cannot read '" + path.string() + "': " + std::strerror(errno));
  return data;
}

}  // namespace isovdb::io
