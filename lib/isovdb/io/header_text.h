// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file header_text.h
/// @brief Internal text helpers shared by the header readers of dense volume
///        files (nrrd_reader.cc, metaimage_reader.cc). Not part of the public API.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace isovdb::io::detail {

/// Longest text header of a volume file we accept (a header is a few hundred bytes).
inline constexpr std::int64_t kMaxHeaderBytes = std::int64_t{1} << 20;

/// Base of the readers' field tables: how error messages name the header file, and failing with it.
class HeaderFields {
 public:
  /// @param[in] where how messages start, e.g. "'vol.nhdr': ".
  explicit HeaderFields(std::string where) : where_(std::move(where)) {}

  const std::string& where() const { return where_; }
  /// @throw InputError "<where>field '<field>': <problem>", always.
  [[noreturn]] void fail(const std::string& field, const std::string& problem) const;
  /// Checks that a header read up to byte `position` is not longer than kMaxHeaderBytes.
  /// @throw InputError "<where>header longer than ... bytes <missingEnd>" when it is.
  void checkHeaderLength(std::int64_t position, const std::string& missingEnd) const;

 private:
  std::string where_;
};

/// `text` without leading and trailing white space.
std::string trim(std::string_view text);
/// `text` on one line: line breaks become spaces (a comment in a file header).
std::string oneLine(std::string text);
/// `text` with ASCII letters in lower case.
std::string lower(std::string text);
/// The white-space separated words of `text` (none for blank text).
std::vector<std::string> splitWords(std::string_view text);
/// The whole of `text` as a decimal integer (an optional leading '+'), or std::nullopt.
std::optional<std::int64_t> parseInt(std::string_view text);
/// The whole of `text` as a number (an optional leading '+'; may be Inf or NaN), or std::nullopt.
std::optional<double> parseDouble(std::string_view text);
/// "X x Y x Z" for messages.
std::string joinDims(const std::array<std::int64_t, 3>& dims);

/// Why the value of a header's data file field does not name one detached data
/// file ("is empty", or a list or pattern of several files), or "" when it does.
std::string dataFileProblem(const std::string& dataFile);
/// The detached data file `dataFile` named in the header at `headerPath`; a
/// relative name is taken from the header's folder.
std::filesystem::path dataFilePath(const std::filesystem::path& headerPath, const std::string& dataFile);

}  // namespace isovdb::io::detail
