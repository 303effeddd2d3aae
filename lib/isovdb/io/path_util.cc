// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/path_util.h"

#include "isovdb/io/header_text.h"

namespace isovdb::io {

std::string lowerExtension(const std::filesystem::path& path) { return detail::lower(path.extension().string()); }

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

}  // namespace isovdb::io
