// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/byte_stream.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <climits>
#include <cstring>
#include <new>

#include "isovdb/errors.h"
#include "isovdb/io/path_util.h"

namespace isovdb::io {

namespace {

/// Largest chunk handed to pread() or zlib at once (zlib counters are 32-bit).
constexpr std::size_t kMaxChunk = std::size_t{1} << 30;

}  // namespace

// --- ByteStream -----------------------------------------------------------------

std::size_t ByteStream::read(std::byte* out, std::size_t size) {
  std::size_t total = 0;
  while (total < size) {
    const std::size_t got = readSome(out + total, size - total);
    if (got == 0) break;
    total += got;
  }
  position_ += static_cast<std::int64_t>(total);
  return total;
}

void ByteStream::readExact(std::byte* out, std::size_t size, std::int64_t expectedTotal) {
  const std::int64_t start = position_;
  const std::size_t got = read(out, size);
  if (got == size) return;
  const std::int64_t expected = expectedTotal >= 0 ? expectedTotal : start + static_cast<std::int64_t>(size);
  throw InputError(label_ + ": " + dataNoun() + " ends after " + std::to_string(position_) + " of " +
                   std::to_string(expected) + " bytes");
}

std::int64_t ByteStream::skipSome(std::int64_t count) {
  std::array<std::byte, 64 * 1024> scratch;
  std::int64_t total = 0;
  while (total < count) {
    const std::size_t want = static_cast<std::size_t>(std::min<std::int64_t>(count - total, scratch.size()));
    const std::size_t got = readSome(scratch.data(), want);
    if (got == 0) break;
    total += static_cast<std::int64_t>(got);
  }
  return total;
}

void ByteStream::skip(std::int64_t count) {
  if (count <= 0) return;
  const std::int64_t got = skipSome(count);
  position_ += got;
  if (got < count)
    throw InputError(label_ + ": " + dataNoun() + " ends after " + std::to_string(got) + " of the " +
                     std::to_string(count) + " bytes to skip");
}

void ByteStream::skipLines(std::int64_t count) {
  for (std::int64_t line = 0; line < count; ++line) {
    std::byte byte{};
    do {
      if (read(&byte, 1) == 0)
        throw InputError(label_ + ": " + dataNoun() + " ends inside line " + std::to_string(line + 1) + " of the " +
                         std::to_string(count) + " lines to skip");
    } while (byte != std::byte{'\n'});
  }
}

std::optional<std::string> ByteStream::readLine(std::size_t maxLength) {
  std::string line;
  std::byte byte{};
  bool any = false;
  while (read(&byte, 1) == 1) {
    any = true;
    if (byte == std::byte{'\n'}) break;
    if (line.size() >= maxLength)
      throw InputError(label_ + ": header line longer than " + std::to_string(maxLength) +
                       " bytes (is this a text header?)");
    line.push_back(static_cast<char>(byte));
  }
  if (!any) return std::nullopt;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

// --- FileRegionStream -------------------------------------------------------------

FileRegionStream::FileRegionStream(const std::filesystem::path& path, const FileRegionOptions& options)
    : ByteStream(options.label.empty() ? quoted(path) : options.label),
      path_(path),
      bufferSize_(std::max<std::size_t>(options.bufferSize, 1)) {
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) {
    if (errno == ENOENT) throw IoError(quoted(path) + ": no such file");
    throw IoError(quoted(path) + ": cannot open: " + std::strerror(errno));
  }
  struct stat info {};
  if (::fstat(fd_, &info) != 0) {
    const std::string why = std::strerror(errno);
    ::close(fd_);
    throw IoError(quoted(path) + ": cannot stat: " + why);
  }
  if (S_ISDIR(info.st_mode)) {
    ::close(fd_);
    throw IoError(quoted(path) + ": is a directory, not a file");
  }
  fileSize_ = static_cast<std::int64_t>(info.st_size);
  if (options.offset < 0 || options.offset > fileSize_) {
    ::close(fd_);
    throw InputError(label() + ": data offset " + std::to_string(options.offset) + " lies outside the file (" +
                     std::to_string(fileSize_) + " bytes)");
  }
  regionEnd_ = fileSize_;
  if (options.length >= 0) {
    if (options.length > fileSize_ - options.offset) {
      ::close(fd_);
      throw InputError(label() + ": file ends after " + std::to_string(fileSize_ - options.offset) + " of " +
                       std::to_string(options.length) + " bytes (data starts at offset " +
                       std::to_string(options.offset) + ")");
    }
    regionEnd_ = options.offset + options.length;
  }
  cursor_ = options.offset;
}

FileRegionStream::~FileRegionStream() {
  if (fd_ >= 0) ::close(fd_);
}

std::int64_t FileRegionStream::remaining() const {
  return regionEnd_ - cursor_ + static_cast<std::int64_t>(bufferEnd_ - bufferBegin_);
}

std::size_t FileRegionStream::preadSome(std::byte* out, std::size_t size) {
  const std::size_t want = static_cast<std::size_t>(
      std::min<std::int64_t>(static_cast<std::int64_t>(std::min<std::size_t>(size, kMaxChunk)), regionEnd_ - cursor_));
  if (want == 0) return 0;
  for (;;) {
    const ssize_t got = ::pread(fd_, out, want, static_cast<off_t>(cursor_));
    if (got >= 0) {
      cursor_ += got;
      return static_cast<std::size_t>(got);
    }
    if (errno != EINTR) throw IoError(quoted(path_) + ": read failed: " + std::strerror(errno));
  }
}

std::size_t FileRegionStream::readSome(std::byte* out, std::size_t size) {
  if (bufferBegin_ == bufferEnd_) {
    // Large reads go straight to the caller; small ones refill the buffer.
    if (size >= bufferSize_) return preadSome(out, size);
    if (buffer_.empty())
      buffer_.resize(static_cast<std::size_t>(std::min<std::int64_t>(static_cast<std::int64_t>(bufferSize_),
                                                                     std::max<std::int64_t>(regionEnd_ - cursor_, 1))));
    bufferBegin_ = 0;
    bufferEnd_ = preadSome(buffer_.data(), buffer_.size());
    if (bufferEnd_ == 0) return 0;
  }
  const std::size_t n = std::min(size, bufferEnd_ - bufferBegin_);
  std::memcpy(out, buffer_.data() + bufferBegin_, n);
  bufferBegin_ += n;
  return n;
}

std::int64_t FileRegionStream::skipSome(std::int64_t count) {
  const std::int64_t fromBuffer = std::min<std::int64_t>(count, static_cast<std::int64_t>(bufferEnd_ - bufferBegin_));
  bufferBegin_ += static_cast<std::size_t>(fromBuffer);
  const std::int64_t fromFile = std::min(count - fromBuffer, regionEnd_ - cursor_);
  cursor_ += fromFile;
  return fromBuffer + fromFile;
}

// --- CompressedInput --------------------------------------------------------------

CompressedInput::CompressedInput(std::unique_ptr<ByteStream> source, std::size_t bufferSize)
    : source_(std::move(source)), buffer_(std::clamp<std::size_t>(bufferSize, 16, kMaxChunk)) {}

std::pair<std::byte*, std::size_t> CompressedInput::refill(const std::byte* next, std::size_t unread) {
  if (unread > 0 && next != buffer_.data()) std::memmove(buffer_.data(), next, unread);
  const std::size_t got = sourceEnded_ ? 0 : source_->read(buffer_.data() + unread, buffer_.size() - unread);
  if (got == 0) sourceEnded_ = true;
  return {buffer_.data(), unread + got};
}

// --- DecompressingStream ----------------------------------------------------------

void DecompressingStream::finish(std::int64_t expectedTotal) {
  std::array<std::byte, 4096> scratch;
  const std::size_t extra = readSome(scratch.data(), scratch.size());
  if (extra > 0)
    throw InputError(label() + ": decompressed data is longer than the " + std::to_string(expectedTotal) +
                     " bytes the header declares");
}

// --- InflateStream ----------------------------------------------------------------

struct InflateStream::State {
  z_stream z{};
  std::int64_t totalOut = 0;
};

InflateStream::InflateStream(std::unique_ptr<ByteStream> compressed, std::size_t bufferSize)
    : DecompressingStream(compressed->label()),
      state_(std::make_unique<State>()),
      input_(std::move(compressed), bufferSize) {
  // windowBits 15 + 32: accept both zlib and gzip headers.
  const int rc = inflateInit2(&state_->z, 15 + 32);
  if (rc == Z_MEM_ERROR) throw std::bad_alloc();
  if (rc != Z_OK) throw IoError(label() + ": cannot initialise zlib (" + std::to_string(rc) + ")");
}

InflateStream::~InflateStream() { inflateEnd(&state_->z); }

bool InflateStream::refill() {
  z_stream& z = state_->z;
  const std::size_t before = z.avail_in;
  const auto [data, available] = input_.refill(reinterpret_cast<const std::byte*>(z.next_in), z.avail_in);
  z.next_in = reinterpret_cast<Bytef*>(data);
  z.avail_in = static_cast<uInt>(available);
  return available > before;
}

bool InflateStream::startNextMember() {
  z_stream& z = state_->z;
  if (z.avail_in < 2 && !input_.sourceEnded()) refill();
  if (z.avail_in < 2 || z.next_in[0] != 0x1f || z.next_in[1] != 0x8b) return false;
  if (inflateReset(&z) != Z_OK) return false;
  return true;
}

std::size_t InflateStream::readSome(std::byte* out, std::size_t size) {
  if (ended_) return 0;
  z_stream& z = state_->z;
  const std::size_t chunk = std::min(size, kMaxChunk);
  z.next_out = reinterpret_cast<Bytef*>(out);
  z.avail_out = static_cast<uInt>(chunk);
  while (z.avail_out > 0) {
    if (z.avail_in == 0) refill();
    const uInt outBefore = z.avail_out;
    const uInt inBefore = z.avail_in;
    const int rc = inflate(&z, Z_NO_FLUSH);
    state_->totalOut += outBefore - z.avail_out;
    if (rc == Z_STREAM_END) {
      if (!startNextMember()) {
        ended_ = true;
        break;
      }
      continue;
    }
    if (rc == Z_MEM_ERROR) throw std::bad_alloc();
    if (rc == Z_DATA_ERROR || rc == Z_NEED_DICT || rc == Z_STREAM_ERROR)
      throw InputError(label() + ": corrupt compressed data (" + (z.msg ? z.msg : "zlib error " + std::to_string(rc)) +
                       ") after " + std::to_string(state_->totalOut) + " decompressed bytes");
    const bool noProgress = z.avail_out == outBefore && z.avail_in == inBefore;
    if ((rc == Z_BUF_ERROR || noProgress) && z.avail_in == 0 && input_.sourceEnded())
      throw InputError(label() + ": compressed data is truncated (the stream ends after " +
                       std::to_string(state_->totalOut) + " decompressed bytes)");
  }
  return chunk - z.avail_out;
}

}  // namespace isovdb::io
