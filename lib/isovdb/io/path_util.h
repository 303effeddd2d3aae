// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file path_util.h
/// @brief Small helpers on file paths shared by the readers, the writers and pipeline/.
#pragma once

#include <filesystem>
#include <string>

namespace isovdb::io {

/// The extension of `path` with its dot, in lower case (".nrrd", ".ply"); "" when it has none.
/// Picks the file format, so "VOL.NRRD" and "vol.nrrd" read alike.
std::string lowerExtension(const std::filesystem::path& path);

/// `path` in single quotes, as every message names a file ('in.nrrd').
std::string quoted(const std::filesystem::path& path);

}  // namespace isovdb::io
