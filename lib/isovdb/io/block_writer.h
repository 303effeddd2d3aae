// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file block_writer.h
/// @brief Little-endian bytes collected and handed to an AtomicFile in blocks of about
///        1 MiB: the binary mesh writers (PLY, STL, GLB) emit one number at a time.
#pragma once

#include <cstddef>
#include <string>

#include "isovdb/io/atomic_file.h"
#include "isovdb/io/little_endian.h"

namespace isovdb::io {

/// Collects little-endian bytes and hands them to the file in large blocks.
class BlockWriter {
 public:
  explicit BlockWriter(AtomicFile& file) : file_(file) { buffer_.reserve(kBlock + 64); }

  void put(const void* data, std::size_t bytes) {
    buffer_.append(static_cast<const char*>(data), bytes);
    flushIfFull();
  }
  template <class T>
  void putLittleEndian(T value) {
    const auto bytes = littleEndianBytes(value);
    buffer_.append(bytes.data(), bytes.size());
    flushIfFull();
  }
  /// Hands the collected bytes to the file; call once after the last put.
  void flush() {
    if (!buffer_.empty()) file_.write(buffer_);
    buffer_.clear();
  }

 private:
  void flushIfFull() {
    if (buffer_.size() >= kBlock) flush();
  }
  static constexpr std::size_t kBlock = std::size_t{1} << 20;
  AtomicFile& file_;
  std::string buffer_;
};

}  // namespace isovdb::io
