// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/header_text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <system_error>

#include "isovdb/errors.h"

namespace isovdb::io::detail {

namespace {

template <typename T>
std::optional<T> parseNumber(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

}  // namespace

void HeaderFields::fail(const std::string& field, const std::string& problem) const {
  throw InputError(where_ + "field '" + field + "': " + problem);
}

void HeaderFields::checkHeaderLength(std::int64_t position, const std::string& missingEnd) const {
  if (position > kMaxHeaderBytes)
    throw InputError(where_ + "header longer than " + std::to_string(kMaxHeaderBytes) + " bytes " + missingEnd);
}

std::string oneLine(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return text;
}

std::string trim(std::string_view text) {
  const auto isSpace = [](unsigned char c) { return std::isspace(c) != 0; };
  while (!text.empty() && isSpace(text.front())) text.remove_prefix(1);
  while (!text.empty() && isSpace(text.back())) text.remove_suffix(1);
  return std::string(text);
}

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::vector<std::string> splitWords(std::string_view text) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    const std::size_t start = i;
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    if (i > start) words.emplace_back(text.substr(start, i - start));
  }
  return words;
}

std::optional<std::int64_t> parseInt(std::string_view text) { return parseNumber<std::int64_t>(text); }

std::optional<double> parseDouble(std::string_view text) { return parseNumber<double>(text); }

std::string joinDims(const std::array<std::int64_t, 3>& dims) {
  return std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]);
}

std::string dataFileProblem(const std::string& dataFile) {
  const std::vector<std::string> words = splitWords(dataFile);
  if (words.empty()) return "is empty";
  if (words[0] == "LIST" || (words.size() >= 4 && words[0].find('%') != std::string::npos))
    return "multiple data files are not supported ('" + dataFile + "')";
  return {};
}

std::filesystem::path dataFilePath(const std::filesystem::path& headerPath, const std::string& dataFile) {
  std::filesystem::path dataPath(dataFile);
  if (dataPath.is_relative()) dataPath = headerPath.parent_path() / dataPath;
  return dataPath;
}

}  // namespace isovdb::io::detail
