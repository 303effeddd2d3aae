// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/dense_volume.h"

#include <string>
#include <system_error>

#include "isovdb/errors.h"
#include "isovdb/io/header_text.h"
#include "isovdb/io/metaimage_reader.h"
#include "isovdb/io/nifti_reader.h"
#include "isovdb/io/nrrd_reader.h"
#include "isovdb/io/path_util.h"

namespace isovdb::io {

namespace {

enum class DenseFormat { Nrrd, MetaImage, Nifti, Raw };

DenseFormat formatOf(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".nrrd" || ext == ".nhdr") return DenseFormat::Nrrd;
  if (ext == ".mhd" || ext == ".mha") return DenseFormat::MetaImage;
  const std::string name = detail::lower(path.filename().string());
  if (name.ends_with(".nii") || name.ends_with(".nii.gz")) return DenseFormat::Nifti;
  return DenseFormat::Raw;
}

}  // namespace

bool isDenseVolumePath(const std::filesystem::path& path) {
  return formatOf(path) != DenseFormat::Raw || lowerExtension(path) == ".raw";
}

std::unique_ptr<SliceStream> openDenseVolume(const std::filesystem::path& path, const std::optional<RawOptions>& raw) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw IoError("'" + path.string() + "': no such file");
  switch (formatOf(path)) {
    case DenseFormat::Nrrd:
      return openNrrd(path);
    case DenseFormat::MetaImage:
      return openMetaImage(path);
    case DenseFormat::Nifti:
      return openNifti(path);
    case DenseFormat::Raw:
      break;
  }
  if (!raw) throw InputError("'" + path.string() + "': raw volumes need --dims and --type");
  return openRaw(path, *raw);
}

}  // namespace isovdb::io
