// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include "isovdb/errors.h"

namespace isovdb::io {

namespace {

std::string osError() { return std::strerror(errno); }

std::atomic<CommitGroup*> activeGroup{nullptr};

}  // namespace

CommitGroup::CommitGroup() {
  CommitGroup* none = nullptr;
  if (!activeGroup.compare_exchange_strong(none, this)) throw std::logic_error("CommitGroup: another group is alive");
}

CommitGroup::~CommitGroup() {
  activeGroup.store(nullptr);
  std::error_code ec;
  for (const auto& [temporary, path] : pending_) std::filesystem::remove(temporary, ec);
}

void CommitGroup::commitAll() {
  const std::lock_guard lock(mutex_);
  while (!pending_.empty()) {
    const auto [temporary, path] = pending_.front();
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) throw IoError("cannot write '" + path.string() + "': " + ec.message());
    pending_.erase(pending_.begin());
  }
}

std::filesystem::path CommitGroup::readablePath(const std::filesystem::path& path) {
  CommitGroup* group = activeGroup.load();
  if (!group) return path;
  const std::lock_guard lock(group->mutex_);
  for (const auto& [temporary, pending] : group->pending_)
    if (pending == path) return temporary;
  return path;
}

bool CommitGroup::defer(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  CommitGroup* group = activeGroup.load();
  if (!group) return false;
  const std::lock_guard lock(group->mutex_);
  group->pending_.emplace_back(temporary, path);
  return true;
}

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  if (path_.empty()) throw IoError("output path is empty");
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec))
    throw IoError("cannot write '" + path_.string() + "': it is a directory");
  const std::filesystem::path dir = path_.has_parent_path() ? path_.parent_path() : ".";
  // mkstemp gives a unique name, so concurrent writers of one directory do not collide.
  std::string pattern = (dir / ("." + path_.filename().string() + ".tmp.XXXXXX")).string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) throw IoError("cannot write '" + path_.string() + "': " + osError());
  tmpPath_ = pattern;
  file_ = ::fdopen(fd, "wb");
  if (!file_) {
    const std::string why = osError();
    ::close(fd);
    std::filesystem::remove(tmpPath_, ec);
    throw IoError("cannot write '" + path_.string() + "': " + why);
  }
}

AtomicFile::~AtomicFile() {
  if (file_) std::fclose(file_);
  if (!committed_) {
    std::error_code ec;
    std::filesystem::remove(tmpPath_, ec);
  }
}

void AtomicFile::checkWritable(const std::filesystem::path& path) {
  AtomicFile probe(path);  // creates and, not committed, removes the temporary
}

void AtomicFile::write(const void* data, std::size_t bytes) {
  if (!file_) throw IoError("cannot write '" + path_.string() + "': stream already closed");
  if (bytes && std::fwrite(data, 1, bytes, file_) != bytes)
    throw IoError("cannot write '" + path_.string() + "': " + osError());
}

void AtomicFile::overwrite(std::uint64_t offset, const void* data, std::size_t bytes) {
  if (!file_) throw IoError("cannot write '" + path_.string() + "': stream already closed");
  if (std::fseek(file_, static_cast<long>(offset), SEEK_SET) != 0)
    throw IoError("cannot write '" + path_.string() + "': " + osError());
  write(data, bytes);
  if (std::fseek(file_, 0, SEEK_END) != 0) throw IoError("cannot write '" + path_.string() + "': " + osError());
}

void AtomicFile::flush() {
  if (file_ && std::fflush(file_) != 0) throw IoError("cannot write '" + path_.string() + "': " + osError());
}

void AtomicFile::closeStream() {
  if (!file_) return;
  const bool ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok) throw IoError("cannot write '" + path_.string() + "': " + osError());
}

void AtomicFile::commit() {
  closeStream();
  // mkstemp creates 0600 files; give the output the usual permissions.
  std::error_code ec;
  std::filesystem::permissions(tmpPath_,
                               std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
                                   std::filesystem::perms::group_read | std::filesystem::perms::others_read,
                               ec);
  if (CommitGroup::defer(tmpPath_, path_)) {
    committed_ = true;  // the group renames or removes the temporary
    return;
  }
  std::filesystem::rename(tmpPath_, path_, ec);
  if (ec) throw IoError("cannot write '" + path_.string() + "': " + ec.message());
  committed_ = true;
}

}  // namespace isovdb::io
