// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file bunzip2_stream.h
/// @brief A ByteStream that decompresses bzip2 data (libbz2) read from another stream:
///        NRRD's `encoding: bzip2` (written by Teem's unu and by pynrrd).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "isovdb/io/byte_stream.h"

namespace isovdb::io {

/// Decompresses bzip2 data as it is read. Concatenated bzip2 streams (pbzip2, `cat a.bz2
/// b.bz2`) are read as one.
class Bunzip2Stream final : public DecompressingStream {
 public:
  /// @param[in] compressed the compressed bytes; its label names the data in messages.
  /// @throw std::bad_alloc when libbz2 cannot allocate its state.
  explicit Bunzip2Stream(std::unique_ptr<ByteStream> compressed, std::size_t bufferSize = kByteStreamBufferSize);
  ~Bunzip2Stream() override;

 protected:
  /// @throw InputError "<label>: corrupt compressed data (...)" or
  ///        "<label>: compressed data is truncated (...)".
  std::size_t readSome(std::byte* out, std::size_t size) override;

 private:
  struct State;
  void refill();
  bool startNextStream();

  std::unique_ptr<State> state_;
  CompressedInput input_;
  bool ended_ = false;
};

}  // namespace isovdb::io
