// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/nifti_reader.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <utility>

#include "isovdb/errors.h"
#include "isovdb/io/byte_stream.h"
#include "isovdb/io/dense_slice_stream.h"
#include "isovdb/io/header_text.h"
#include "isovdb/io/path_util.h"

namespace isovdb::io {

namespace {

constexpr std::size_t kHeaderBytes = 348;

/// The 348 header bytes, read in the file's byte order.
class NiftiHeader {
 public:
  NiftiHeader(const std::array<std::byte, kHeaderBytes>& bytes, bool swap) : bytes_(bytes), swap_(swap) {}

  template <typename T>
  T at(std::size_t offset) const {
    std::array<std::byte, sizeof(T)> raw;
    std::memcpy(raw.data(), bytes_.data() + offset, sizeof(T));
    if (swap_) std::reverse(raw.begin(), raw.end());
    T value;
    std::memcpy(&value, raw.data(), sizeof(T));
    return value;
  }
  std::int16_t dim(int i) const { return at<std::int16_t>(40 + 2 * static_cast<std::size_t>(i)); }
  float pixdim(int i) const { return at<float>(76 + 4 * static_cast<std::size_t>(i)); }
  std::string magic() const {
    std::string m(reinterpret_cast<const char*>(bytes_.data() + 344), 4);
    return m;
  }

 private:
  const std::array<std::byte, kHeaderBytes>& bytes_;
  bool swap_;
};

struct Datatype {
  std::int16_t code;
  const char* name;
  std::optional<SampleType> type;
};

constexpr std::array<Datatype, 16> kDatatypes{{
    {2, "uint8", SampleType::UInt8},
    {4, "int16", SampleType::Int16},
    {8, "int32", SampleType::Int32},
    {16, "float32", SampleType::Float32},
    {64, "float64", SampleType::Float64},
    {256, "int8", SampleType::Int8},
    {512, "uint16", SampleType::UInt16},
    {768, "uint32", SampleType::UInt32},
    {1, "binary", std::nullopt},
    {32, "complex64", std::nullopt},
    {128, "rgb24", std::nullopt},
    {1024, "int64", std::nullopt},
    {1280, "uint64", std::nullopt},
    {1536, "float128", std::nullopt},
    {1792, "complex128", std::nullopt},
    {2304, "rgba32", std::nullopt},
}};

/// Slices of the file's samples, x and/or y reversed (axes whose world step is negative) and
/// scaled by scl_slope / scl_inter.
class NiftiSliceStream final : public SliceStream {
 public:
  NiftiSliceStream(std::unique_ptr<SliceStream> samples, std::array<bool, 2> flip,
                   std::optional<std::pair<float, float>> scale)
      : samples_(std::move(samples)), flip_(flip), scale_(scale) {}

  const std::string& source() const override { return samples_->source(); }
  const VolumeHeader& header() const override { return samples_->header(); }
  std::int64_t nextSlice() const override { return samples_->nextSlice(); }
  void skipSlices(std::int64_t count) override { samples_->skipSlices(count); }

  void readSlice(float* out) override {
    const std::int64_t z = samples_->nextSlice();
    samples_->readSlice(out);
    const auto nx = static_cast<std::size_t>(header().dims[0]), ny = static_cast<std::size_t>(header().dims[1]);
    if (flip_[0])
      for (std::size_t j = 0; j < ny; ++j) std::reverse(out + j * nx, out + (j + 1) * nx);
    if (flip_[1])
      for (std::size_t j = 0; j < ny / 2; ++j)
        std::swap_ranges(out + j * nx, out + (j + 1) * nx, out + (ny - 1 - j) * nx);
    if (!scale_) return;
    const auto [slope, intercept] = *scale_;
    for (std::size_t i = 0; i < nx * ny; ++i) {
      out[i] = out[i] * slope + intercept;
      if (!std::isfinite(out[i]))
        throw InputError(source() + ": sample " + std::to_string(i % nx) + ", " + std::to_string(i / nx) + ", " +
                         std::to_string(z) + " times scl_slope " + std::to_string(slope) + " plus scl_inter " +
                         std::to_string(intercept) + " is not a finite float");
    }
  }

 private:
  std::unique_ptr<SliceStream> samples_;
  std::array<bool, 2> flip_;
  std::optional<std::pair<float, float>> scale_;
};

}  // namespace

std::unique_ptr<SliceStream> openNifti(const std::filesystem::path& path) {
  const std::string source = quoted(path);
  const auto fail = [&](const std::string& field, const std::string& what) -> void {
    throw InputError(source + ": NIfTI header field '" + field + "': " + what);
  };
  const std::string name = detail::lower(path.filename().string());
  const bool gzip = name.size() > 3 && name.ends_with(".gz");
  auto file = std::make_unique<FileRegionStream>(path);
  const FileRegionStream* region = gzip ? nullptr : file.get();  // a raw file's size is checked up front
  std::unique_ptr<ByteStream> bytes;
  if (gzip)
    bytes = std::make_unique<InflateStream>(std::move(file));
  else
    bytes = std::move(file);

  std::array<std::byte, kHeaderBytes> raw{};
  bytes->readExact(raw.data(), raw.size(), static_cast<std::int64_t>(kHeaderBytes));
  std::int32_t size = 0;
  std::memcpy(&size, raw.data(), sizeof size);
  const auto swapped = static_cast<std::int32_t>(__builtin_bswap32(static_cast<std::uint32_t>(size)));
  if (size == 540 || swapped == 540)
    throw InputError(source +
                     ": a NIfTI-2 file (sizeof_hdr 540); isovdb reads NIfTI-1 (convert it, e.g. with nibabel)");
  if (size != static_cast<std::int32_t>(kHeaderBytes) && swapped != static_cast<std::int32_t>(kHeaderBytes))
    fail("sizeof_hdr", "is " + std::to_string(size) + ", a NIfTI-1 file has 348");
  const bool swap = size != static_cast<std::int32_t>(kHeaderBytes);
  const NiftiHeader h(raw, swap);

  const std::string magic = h.magic();
  if (magic == std::string("ni1\0", 4))
    fail("magic", "'ni1': the header of a .hdr/.img pair; isovdb reads single-file .nii volumes");
  if (magic != std::string("n+1\0", 4)) fail("magic", "is not 'n+1' (an ANALYZE 7.5 file, or not NIfTI-1)");

  const int dims = h.dim(0);
  if (dims < 3 || dims > 7) fail("dim", "dim[0] is " + std::to_string(dims) + ": isovdb reads 3-D volumes");
  for (int i = 4; i <= dims; ++i)
    if (h.dim(i) != 1)
      fail("dim", "dim[" + std::to_string(i) + "] is " + std::to_string(h.dim(i)) +
                      " (a time series or vector image): isovdb reads 3-D volumes");
  VolumeHeader header;
  for (int a = 0; a < 3; ++a) header.dims[static_cast<std::size_t>(a)] = h.dim(a + 1);

  const auto code = h.at<std::int16_t>(70);
  const auto* datatype =
      std::find_if(kDatatypes.begin(), kDatatypes.end(), [&](const Datatype& d) { return d.code == code; });
  if (datatype == kDatatypes.end() || !datatype->type)
    fail("datatype", std::to_string(code) +
                         (datatype != kDatatypes.end() ? " (" + std::string(datatype->name) + ")" : "") +
                         " is not supported (uint8, int8, int16, uint16, int32, uint32, float32, float64)");
  header.sampleType = *datatype->type;
  header.bigEndian = swap != (std::endian::native == std::endian::big);
  if (h.at<std::int16_t>(72) != static_cast<std::int16_t>(8 * sampleSize(header.sampleType)))
    fail("bitpix", "is " + std::to_string(h.at<std::int16_t>(72)) + " for datatype " + datatype->name);
  const std::int64_t dataBytes = checkedVolumeBytes(header, source, "NIfTI header field 'dim'");

  const float voxOffset = h.at<float>(108);
  if (!(voxOffset >= static_cast<float>(kHeaderBytes)) || voxOffset != std::floor(voxOffset) || voxOffset > 1e15f)
    fail("vox_offset", "is " + std::to_string(voxOffset) + ", not a byte offset at or after the 348-byte header");

  // The voxel-to-world transform: sform, else qform, else pixdim alone.
  std::array<std::array<double, 3>, 3> m{};
  std::array<double, 3> t{};
  const auto sformCode = h.at<std::int16_t>(254), qformCode = h.at<std::int16_t>(252);
  const char* transformField = "pixdim";
  if (sformCode > 0) {
    transformField = "srow_x/srow_y/srow_z (sform)";
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) m[r][c] = h.at<float>(280 + 16 * static_cast<std::size_t>(r) + 4 * c);
      t[r] = h.at<float>(280 + 16 * static_cast<std::size_t>(r) + 12);
    }
  } else if (qformCode > 0) {
    transformField = "quatern_b/c/d and pixdim (qform)";
    const double b = h.at<float>(256), c = h.at<float>(260), d = h.at<float>(264);
    const double a = std::sqrt(std::max(0.0, 1.0 - (b * b + c * c + d * d)));
    const std::array<std::array<double, 3>, 3> rotation{
        {{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)},
         {2 * (b * c + a * d), a * a + c * c - b * b - d * d, 2 * (c * d - a * b)},
         {2 * (b * d - a * c), 2 * (c * d + a * b), a * a + d * d - c * c - b * b}}};
    const double qfac = h.pixdim(0) < 0 ? -1.0 : 1.0;
    const std::array<double, 3> scale{h.pixdim(1), h.pixdim(2), qfac * h.pixdim(3)};
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 3; ++col) m[r][col] = rotation[r][col] * scale[col];
    for (int r = 0; r < 3; ++r) t[r] = h.at<float>(268 + 4 * static_cast<std::size_t>(r));
  } else {
    for (int a = 0; a < 3; ++a) m[a][a] = h.pixdim(a + 1);
  }
  double largest = 0;
  for (const auto& row : m)
    for (const double v : row) {
      if (!std::isfinite(v)) fail(transformField, "is not finite");
      largest = std::max(largest, std::abs(v));
    }
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (r != c && std::abs(m[r][c]) > 1e-6 * largest)
        fail(transformField, "rotates or swaps the axes; isovdb reads axis-aligned volumes (resample it first)");
  std::array<bool, 2> flip{false, false};
  for (int a = 0; a < 3; ++a) {
    const double step = m[a][a];
    if (!(std::abs(step) > 0)) fail(transformField, "gives axis " + std::to_string(a) + " a zero voxel size");
    if (step < 0 && a == 2)
      fail(transformField,
           "gives z a negative step; isovdb reads slices in increasing world z (flip the volume first)");
    header.spacing[static_cast<std::size_t>(a)] = std::abs(step);
    // A reversed axis starts at its last voxel's world position.
    header.origin[static_cast<std::size_t>(a)] =
        t[a] + (step < 0 ? step * static_cast<double>(header.dims[a] - 1) : 0.0);
    if (a < 2) flip[static_cast<std::size_t>(a)] = step < 0;
  }

  std::optional<std::pair<float, float>> scale;
  const float slope = h.at<float>(112), intercept = h.at<float>(116);
  if (!std::isfinite(slope) || !std::isfinite(intercept)) fail("scl_slope/scl_inter", "is not finite");
  if (slope != 0.0f && !(slope == 1.0f && intercept == 0.0f)) scale = std::make_pair(slope, intercept);

  bytes->skip(static_cast<std::int64_t>(voxOffset) - static_cast<std::int64_t>(kHeaderBytes));
  if (region) {
    if (region->remaining() != dataBytes)
      throw InputError(source + ": the dims need " + std::to_string(dataBytes) + " data bytes after vox_offset " +
                       std::to_string(static_cast<std::int64_t>(voxOffset)) + ", the file holds " +
                       std::to_string(region->remaining()));
  }
  auto samples = std::make_unique<DenseSliceStream>(source, header, std::move(bytes));
  if (!flip[0] && !flip[1] && !scale) return samples;
  return std::make_unique<NiftiSliceStream>(std::move(samples), flip, scale);
}

}  // namespace isovdb::io
