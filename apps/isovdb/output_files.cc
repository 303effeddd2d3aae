// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include <filesystem>
#include <string>
#include <vector>

#include "commands.h"
#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"

namespace isovdb::cli {

namespace {

/// The path as the file system resolves it (symbolic links, `..`), also for a file
/// that does not exist yet.
std::filesystem::path resolved(const std::string& path) {
  std::error_code ec;
  std::filesystem::path p = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  return ec ? std::filesystem::path(path).lexically_normal() : p;
}

}  // namespace

void checkFilesBeforeWork(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) {
  std::vector<std::pair<const NamedFile*, std::filesystem::path>> seen;
  for (const NamedFile& input : inputs)
    if (!input.path.empty()) seen.emplace_back(&input, resolved(input.path));
  for (const NamedFile& output : outputs) {
    if (output.path.empty()) continue;
    const std::filesystem::path path = resolved(output.path);
    for (const auto& [other, otherPath] : seen)
      if (otherPath == path)
        throw InputError("'" + output.path + "': " + output.option + " and " + other->option +
                         " name the same file: it would be overwritten; choose another path");
    io::AtomicFile::checkWritable(output.path);
    seen.emplace_back(&output, path);
  }
}

}  // namespace isovdb::cli
