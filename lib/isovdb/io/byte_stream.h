// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file byte_stream.h
/// @brief Sequential, buffered byte sources for the dense volume readers: a
///        region of a file and a zlib/gzip inflating stream over another source.
///
/// Memory: each stream holds one fixed buffer (1 MiB by default) and never the
/// whole file; reads larger than the buffer go straight into the caller's memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace isovdb::io {

/// Default size of the buffer of each byte stream (1 MiB).
inline constexpr std::size_t kByteStreamBufferSize = std::size_t{1} << 20;

/// A sequential source of bytes, read once from the front.
class ByteStream {
 public:
  /// @param[in] label how messages name the data, already quoted, e.g. "'vol.raw'"
  ///            or "'vol.raw.gz' (data file of 'vol.nhdr')".
  explicit ByteStream(std::string label) : label_(std::move(label)) {}
  virtual ~ByteStream() = default;
  ByteStream(const ByteStream&) = delete;
  ByteStream& operator=(const ByteStream&) = delete;

  /// How error messages name this data (quoted file name, maybe with context).
  const std::string& label() const { return label_; }
  /// Bytes delivered (read or skipped) so far.
  std::int64_t position() const { return position_; }

  /// Reads up to `size` bytes into `out`; fewer only at the end of the data.
  /// @return the number of bytes read (0 at the end).
  /// @throw InputError for corrupt or truncated compressed data; IoError when the OS read fails.
  std::size_t read(std::byte* out, std::size_t size);

  /// Reads exactly `size` bytes into `out`.
  /// @param[in] expectedTotal the total the caller expects the data to hold, for
  ///            the message; -1 means position() + size.
  /// @throw InputError "<label>: file ends after N of M bytes" when the data ends
  ///        early (M = expectedTotal), plus the errors of read().
  void readExact(std::byte* out, std::size_t size, std::int64_t expectedTotal = -1);

  /// Discards the next `count` bytes (NRRD "byte skip").
  /// @throw InputError when the data ends first.
  void skip(std::int64_t count);

  /// Discards everything up to and including the next `count` newlines (NRRD "line skip").
  /// @throw InputError when the data ends first.
  void skipLines(std::int64_t count);

  /// Reads one text line (up to '\n', which is dropped, as is a trailing '\r').
  /// @return std::nullopt at the end of the data when no byte was left.
  /// @throw InputError when the line is longer than `maxLength` bytes (not a text header).
  std::optional<std::string> readLine(std::size_t maxLength = 64 * 1024);

  /// Checks that the data holds exactly `expectedTotal` bytes, once they have all
  /// been read. A file region does nothing (its size is checked when opened); an
  /// inflating stream checks the stream end (and checksum) and that no extra data follows.
  /// @throw InputError naming the data when it is truncated or longer than declared.
  virtual void finish(std::int64_t expectedTotal) {}

 protected:
  /// Reads up to `size` (> 0) bytes; returns 0 only at the end of the data.
  virtual std::size_t readSome(std::byte* out, std::size_t size) = 0;
  /// Discards up to `count` bytes; returns how many were discarded (fewer only at the end).
  /// The default reads into a scratch buffer.
  virtual std::int64_t skipSome(std::int64_t count);
  /// What ends early in "... ends after N of M bytes" ("file" or "decompressed data").
  virtual const char* dataNoun() const { return "file"; }

 private:
  std::string label_;
  std::int64_t position_ = 0;
};

/// Where a FileRegionStream reads.
struct FileRegionOptions {
  std::int64_t offset = 0;                         ///< byte offset of the region in the file (>= 0)
  std::int64_t length = -1;                        ///< bytes in the region; -1 = up to the end of the file
  std::string label{};                             ///< how messages name the data; empty = "'<path>'"
  std::size_t bufferSize = kByteStreamBufferSize;  ///< read buffer (bytes); larger reads bypass it
};

/// The bytes of one region of a file, read with pread() through a fixed buffer.
class FileRegionStream final : public ByteStream {
 public:
  /// Opens `path` and checks that the region lies inside the file.
  /// @throw IoError "'path': no such file" (or the OS reason) when it cannot be opened;
  ///        InputError when the region starts or ends past the end of the file.
  explicit FileRegionStream(const std::filesystem::path& path, const FileRegionOptions& options = {});
  ~FileRegionStream() override;

  const std::filesystem::path& path() const { return path_; }
  /// Size of the whole file in bytes.
  std::int64_t fileSize() const { return fileSize_; }
  /// Bytes of the region not yet read or skipped.
  std::int64_t remaining() const;

 protected:
  std::size_t readSome(std::byte* out, std::size_t size) override;
  std::int64_t skipSome(std::int64_t count) override;

 private:
  std::size_t preadSome(std::byte* out, std::size_t size);

  std::filesystem::path path_;
  int fd_ = -1;
  std::int64_t fileSize_ = 0;
  std::int64_t regionEnd_ = 0;  ///< absolute file offset where the region ends
  std::int64_t cursor_ = 0;     ///< absolute file offset of the next byte to pread
  std::vector<std::byte> buffer_;
  std::size_t bufferBegin_ = 0;
  std::size_t bufferEnd_ = 0;
  std::size_t bufferSize_ = kByteStreamBufferSize;
};

/// The compressed bytes a decompressor reads (InflateStream, Bunzip2Stream): a buffer
/// refilled from the source stream, unread input kept at its front.
class CompressedInput {
 public:
  CompressedInput(std::unique_ptr<ByteStream> source, std::size_t bufferSize);

  /// Moves the `unread` bytes at `next` (inside the buffer, or none) to the front and reads
  /// more after them. @return the buffer's start and the bytes now available.
  std::pair<std::byte*, std::size_t> refill(const std::byte* next, std::size_t unread);
  /// True once the source has no more bytes.
  bool sourceEnded() const { return sourceEnded_; }

 private:
  std::unique_ptr<ByteStream> source_;
  std::vector<std::byte> buffer_;
  bool sourceEnded_ = false;
};

/// A stream that decompresses another (InflateStream, Bunzip2Stream).
class DecompressingStream : public ByteStream {
 public:
  using ByteStream::ByteStream;

  /// Drives the decompressor to the end of its data (a missing checksum or end mark
  /// counts as truncation) and checks that nothing follows the declared bytes.
  /// @throw InputError "<label>: decompressed data is longer than the N bytes the header
  ///        declares", or readSome()'s errors.
  void finish(std::int64_t expectedTotal) final;

 protected:
  const char* dataNoun() const override { return "decompressed data"; }
};

/// Inflates zlib or gzip data (zlib's inflate, windowBits 15 + 32 detects either
/// header) read from another stream. Concatenated gzip members are read as one stream.
class InflateStream final : public DecompressingStream {
 public:
  /// @param[in] compressed the compressed bytes; its label names the data in messages.
  /// @throw std::bad_alloc when zlib cannot allocate its state.
  explicit InflateStream(std::unique_ptr<ByteStream> compressed, std::size_t bufferSize = kByteStreamBufferSize);
  ~InflateStream() override;

 protected:
  /// @throw InputError "<label>: corrupt compressed data (...)" or
  ///        "<label>: compressed data is truncated (...)".
  std::size_t readSome(std::byte* out, std::size_t size) override;

 private:
  struct State;
  bool refill();
  bool startNextMember();

  std::unique_ptr<State> state_;
  CompressedInput input_;
  bool ended_ = false;
};

}  // namespace isovdb::io
