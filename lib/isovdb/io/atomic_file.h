// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file atomic_file.h
/// @brief Writes a file through a temporary beside it and renames it on commit,
///        so a failed or interrupted run never leaves a partial output file.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace isovdb::io {

class AtomicFile {
 public:
  /// Opens a temporary file in the directory of `path`.
  /// @throw IoError naming `path` when the directory is missing or not writable.
  explicit AtomicFile(std::filesystem::path path);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Appends bytes. @throw IoError on a failed write (disk full, ...).
  void write(const void* data, std::size_t bytes);
  void write(const std::string& text) { write(text.data(), text.size()); }

  /// Overwrites bytes already written at `offset` (a header whose counts are
  /// known only at the end), then continues appending at the end.
  /// @throw IoError on a failed seek or write.
  void overwrite(std::uint64_t offset, const void* data, std::size_t bytes);

  /// Flushes buffered bytes to the temporary file (so it can be read back).
  /// @throw IoError on failure.
  void flush();

  /// Flushes, closes and renames the temporary onto the final path (while a
  /// CommitGroup is alive, the rename waits for the group's commitAll()).
  /// @throw IoError when any of those fails (the temporary is removed).
  void commit();

  /// Path of the temporary file (for writers that need a filename, like OpenVDB's).
  const std::filesystem::path& temporaryPath() const { return tmpPath_; }
  const std::filesystem::path& path() const { return path_; }

  /// Fails early, before long work, when `path` could not be written later.
  /// @throw IoError naming `path`.
  static void checkWritable(const std::filesystem::path& path);

  /// Closes the stream so another library can write temporaryPath() itself;
  /// commit() then only renames.
  void closeStream();

 private:
  std::filesystem::path path_;
  std::filesystem::path tmpPath_;
  std::FILE* file_ = nullptr;
  bool committed_ = false;
};

/// @brief The outputs of one command, all or none: while a group is alive, every
///        AtomicFile commit (from any thread) is complete on disk but its rename
///        waits for commitAll(). A run that fails after its first output, say the
///        disk filling while the statistics are written after the mesh, leaves no
///        output and no temporary. One group at a time (the CLI's, around a command).
class CommitGroup {
 public:
  CommitGroup();
  /// Removes the temporaries of the files not yet renamed.
  ~CommitGroup();
  CommitGroup(const CommitGroup&) = delete;
  CommitGroup& operator=(const CommitGroup&) = delete;

  /// Renames every committed file onto its path, in commit order.
  /// @throw IoError naming the first path that could not be renamed.
  void commitAll();

  /// Where the bytes committed for `path` are now: the temporary while its rename
  /// waits, else `path` (a command that reads back an output it wrote).
  static std::filesystem::path readablePath(const std::filesystem::path& path);

 private:
  friend class AtomicFile;
  /// Takes the rename of a committed temporary; false when no group is alive.
  static bool defer(const std::filesystem::path& temporary, const std::filesystem::path& path);

  std::mutex mutex_;
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> pending_;  // temporary, path
};

}  // namespace isovdb::io
