// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/bunzip2_stream.h"

#include <bzlib.h>

#include <algorithm>
#include <cstring>
#include <new>
#include <string>

#include "isovdb/errors.h"

namespace isovdb::io {

namespace {

/// libbz2 counts in unsigned int: reads are split into chunks below that.
constexpr std::size_t kMaxChunk = std::size_t{1} << 30;

std::string bzipError(int rc) {
  switch (rc) {
    case BZ_DATA_ERROR:
      return "bad block checksum or data";
    case BZ_DATA_ERROR_MAGIC:
      return "not bzip2 data";
    default:
      return "libbz2 error " + std::to_string(rc);
  }
}

}  // namespace

struct Bunzip2Stream::State {
  bz_stream bz{};
  bool open = false;  ///< BZ2_bzDecompressInit succeeded and End is due
  std::int64_t totalOut = 0;

  void init(const std::string& label) {
    bz = bz_stream{};
    const int rc = BZ2_bzDecompressInit(&bz, 0, 0);
    if (rc == BZ_MEM_ERROR) throw std::bad_alloc();
    if (rc != BZ_OK) throw IoError(label + ": cannot initialise libbz2 (" + std::to_string(rc) + ")");
    open = true;
  }
  void end() {
    if (open) BZ2_bzDecompressEnd(&bz);
    open = false;
  }
};

Bunzip2Stream::Bunzip2Stream(std::unique_ptr<ByteStream> compressed, std::size_t bufferSize)
    : DecompressingStream(compressed->label()),
      state_(std::make_unique<State>()),
      input_(std::move(compressed), bufferSize) {
  state_->init(label());
}

Bunzip2Stream::~Bunzip2Stream() { state_->end(); }

void Bunzip2Stream::refill() {
  bz_stream& bz = state_->bz;
  const auto [data, available] = input_.refill(reinterpret_cast<const std::byte*>(bz.next_in), bz.avail_in);
  bz.next_in = reinterpret_cast<char*>(data);
  bz.avail_in = static_cast<unsigned>(available);
}

bool Bunzip2Stream::startNextStream() {
  bz_stream& bz = state_->bz;
  if (bz.avail_in < 3 && !input_.sourceEnded()) refill();
  if (bz.avail_in < 3 || std::memcmp(bz.next_in, "BZh", 3) != 0) return false;
  // A fresh decompressor for the next stream, keeping the unread input.
  char* const nextIn = bz.next_in;
  const unsigned availIn = bz.avail_in;
  state_->end();
  state_->init(label());
  state_->bz.next_in = nextIn;
  state_->bz.avail_in = availIn;
  return true;
}

std::size_t Bunzip2Stream::readSome(std::byte* out, std::size_t size) {
  if (ended_) return 0;
  const std::size_t chunk = std::min(size, kMaxChunk);
  std::size_t produced = 0;
  while (produced < chunk) {
    bz_stream& bz = state_->bz;
    if (bz.avail_in == 0) refill();
    bz.next_out = reinterpret_cast<char*>(out + produced);
    bz.avail_out = static_cast<unsigned>(chunk - produced);
    const unsigned outBefore = bz.avail_out, inBefore = bz.avail_in;
    const int rc = BZ2_bzDecompress(&bz);
    produced += outBefore - bz.avail_out;
    state_->totalOut += outBefore - bz.avail_out;
    if (rc == BZ_STREAM_END) {
      if (!startNextStream()) {
        ended_ = true;
        break;
      }
      continue;
    }
    if (rc == BZ_MEM_ERROR) throw std::bad_alloc();
    if (rc != BZ_OK)
      throw InputError(label() + ": corrupt compressed data (" + bzipError(rc) + ") after " +
                       std::to_string(state_->totalOut) + " decompressed bytes");
    const bool noProgress = bz.avail_out == outBefore && bz.avail_in == inBefore;
    if (noProgress && bz.avail_in == 0 && input_.sourceEnded())
      throw InputError(label() + ": compressed data is truncated (the stream ends after " +
                       std::to_string(state_->totalOut) + " decompressed bytes)");
  }
  return produced;
}

}  // namespace isovdb::io
