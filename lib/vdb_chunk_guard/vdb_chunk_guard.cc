// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file vdb_chunk_guard.cc
/// @brief Checks each compressed chunk's declared length before OpenVDB 10's
///        `io::bloscFromStream` and `io::unzipFromStream` act on it.
///
/// Both read an int64 length, then (length <= 0) read -length raw bytes into a buffer
/// of `numBytes` and compare the two only afterwards: a damaged `.vdb` overflows the
/// heap (fuzz_vdb: `malloc(): invalid size`, `free(): invalid pointer` in Release),
/// or (length > 0) allocate `length` bytes for the compressed data: terabytes from a
/// flipped byte. This file defines both functions again, so that every call, OpenVDB's
/// own through its procedure linkage table too, reaches the check first: it peeks at
/// the length, refuses one that cannot describe a buffer of `numBytes` with OpenVDB's
/// RuntimeError (which store/vdb_file.cc reports as a damaged file), and hands the
/// stream, untouched, to OpenVDB's function (found with dlsym). Kept apart from the
/// stages, in a library linked before OpenVDB into every executable (lib/CMakeLists.txt).
#include <dlfcn.h>

#include <openvdb/Exceptions.h>
#include <openvdb/io/Compression.h>
#include <openvdb/version.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <sstream>
#include <string>

namespace {

/// What precedes a chunk: its length, or why there is none to read.
struct ChunkLength {
  enum class State { Read, Missing, Unknown } state = State::Unknown;
  std::int64_t value = 0;
};

/// The next 8 bytes of `is` as OpenVDB's chunk length, the stream left where it was.
/// Missing: the stream failed before or ends within them (OpenVDB would go on with an
/// uninitialised length: garbage sizes under ASan, "a 0-byte chunk" in Release).
/// Unknown: they could not be put back (not seekable); left to OpenVDB.
ChunkLength peekChunkLength(std::istream& is) {
  std::streambuf* buffer = is.rdbuf();
  std::array<char, sizeof(std::int64_t)> bytes{};
  if (buffer == nullptr || !is.good()) return {ChunkLength::State::Missing};
  if (buffer->in_avail() >= static_cast<std::streamsize>(bytes.size())) {
    // In the get area already: read and step back without a system call (one per leaf).
    buffer->sgetn(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    for (std::size_t i = 0; i < bytes.size(); ++i) buffer->sungetc();
  } else {
    const std::istream::pos_type start = is.tellg();
    if (start == std::istream::pos_type(-1)) return {ChunkLength::State::Unknown};
    const bool read = static_cast<bool>(is.read(bytes.data(), static_cast<std::streamsize>(bytes.size())));
    is.clear();
    is.seekg(start);
    if (!read) return {ChunkLength::State::Missing};
  }
  ChunkLength length{ChunkLength::State::Read};
  std::memcpy(&length.value, bytes.data(), sizeof(length.value));
  return length;
}

/// Throws when the chunk about to be read into `numBytes` bytes at `data` declares a
/// length it cannot have: raw (<= 0) of another size, or compressed (> 0) beyond what
/// the codec can produce from `numBytes` (`overhead`: blosc's 16-byte header, zlib's
/// compressBound). With `data` null OpenVDB only seeks past the chunk, whose length
/// must still be there.
void checkChunk(std::istream& is, const char* data, std::size_t numBytes, std::size_t overhead, const char* codec) {
  const ChunkLength chunk = peekChunkLength(is);
  if (chunk.state == ChunkLength::State::Missing)
    OPENVDB_THROW(openvdb::RuntimeError, "damaged compressed data: the data ends before a chunk's length");
  if (chunk.state == ChunkLength::State::Unknown || data == nullptr) return;
  const std::int64_t length = chunk.value;
  std::ostringstream message;
  if (length <= 0) {
    // -length without overflow: INT64_MIN has no positive counterpart.
    const std::uint64_t raw = length == std::numeric_limits<std::int64_t>::min() ? std::uint64_t{1} << 63
                                                                                 : static_cast<std::uint64_t>(-length);
    if (raw == numBytes) return;
    message << "a raw chunk of " << raw << " bytes for a " << numBytes << "-byte buffer";
  } else {
    if (static_cast<std::uint64_t>(length) <= numBytes + overhead) return;
    message << "a " << codec << " chunk of " << length << " bytes for a " << numBytes << "-byte buffer (at most "
            << numBytes + overhead << ")";
  }
  OPENVDB_THROW(openvdb::RuntimeError, "damaged compressed data: " + message.str());
}

/// OpenVDB's own function named `name` (the library loaded after this object), or a
/// message naming what is missing. Mangled as the header declares it, in this
/// OpenVDB's version namespace.
template <class Function>
Function* openVdbFunction(const char* name) {
  const std::string version = OPENVDB_PREPROC_STRINGIFY(OPENVDB_VERSION_NAME);
  const std::string mangled = "_ZN7openvdb" + std::to_string(version.size()) + version + "2io" +
                              std::to_string(std::strlen(name)) + name + "ERSiPcm";
  void* symbol = dlsym(RTLD_NEXT, mangled.c_str());
  if (symbol == nullptr) OPENVDB_THROW(openvdb::RuntimeError, "the OpenVDB library has no " + mangled);
  return reinterpret_cast<Function*>(symbol);  // NOLINT(cppcoreguidelines-pro-type-reinterpret-cast)
}

using ChunkReader = void(std::istream&, char*, std::size_t);

}  // namespace

// These definitions take the place of OpenVDB's for every caller, OpenVDB's own code
// included (its calls go through the dynamic linker, which finds the executable's or the
// module's definition first), check the chunk and call OpenVDB's.
namespace openvdb {
OPENVDB_USE_VERSION_NAMESPACE
namespace OPENVDB_VERSION_NAME {
namespace io {

void bloscFromStream(std::istream& is, char* data, std::size_t numBytes) {
  static ChunkReader* const real = openVdbFunction<ChunkReader>("bloscFromStream");
  checkChunk(is, data, numBytes, /*blosc's BLOSC_MAX_OVERHEAD=*/16, "blosc");
  real(is, data, numBytes);
}

void unzipFromStream(std::istream& is, char* data, std::size_t numBytes) {
  static ChunkReader* const real = openVdbFunction<ChunkReader>("unzipFromStream");
  // zlib's compressBound: n + n/4096 + n/16384 + n/2^25 + 13; rounded up.
  checkChunk(is, data, numBytes, numBytes / 2048 + 64, "zlib");
  real(is, data, numBytes);
}

}  // namespace io
}  // namespace OPENVDB_VERSION_NAME
}  // namespace openvdb
