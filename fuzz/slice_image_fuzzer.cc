// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// libFuzzer harness of the slice images `isovdb morph` reads: the input is written as
// a .bmp when its first byte is 'B' (a BMP's signature), else as a .png, so seeds of
// both kinds keep their kind. The pixel limit is lowered to 2^20, so declared sizes
// above it are refused before decoding.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "isovdb/morph/slice_image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool bmp = size > 0 && data[0] == 'B';
  const auto path = isovdb::fuzz::writeInput(data, size, bmp ? ".bmp" : ".png");
  isovdb::fuzz::expectCleanOutcome([&] { isovdb::morph::readSliceImage(path, std::int64_t{1} << 20); });
  return 0;
}
