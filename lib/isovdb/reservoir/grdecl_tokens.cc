// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/reservoir/grdecl_tokens.h"

#include "isovdb/huge_pages.h"

namespace isovdb::reservoir {
namespace {

/// White space as the "C" locale's `isspace` has it, inline: `std::isspace` is a call per
/// character into the C library and was the largest part of reading a deck (perf on Reek:
/// 14 % of a whole `isovdb reservoir` run), and it would follow a caller's locale.
constexpr bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace

std::vector<GrdeclToken> tokenizeGrdecl(std::string_view text) {
  std::vector<GrdeclToken> tokens;
  reserveHuge(tokens, text.size() / 8);  // numbers of a few digits and a space
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (isBlank(c)) {
      ++i;
    } else if (c == '-' && i + 1 < n && text[i + 1] == '-') {
      while (i < n && text[i] != '\n') ++i;
    } else if (c == '\'' || c == '"') {
      const std::size_t end = text.find(c, i + 1);
      const std::size_t stop = end == std::string_view::npos ? n : end;
      tokens.push_back({text.substr(i + 1, stop - i - 1), line, true});
      for (std::size_t k = i; k < stop; ++k) line += text[k] == '\n';
      i = stop + 1;
    } else if (c == '/') {
      tokens.push_back({"/", line, false});
      ++i;
    } else {
      const std::size_t start = i;
      while (i < n && !isBlank(text[i]) && text[i] != '/' && text[i] != '\'' && text[i] != '"' &&
             !(text[i] == '-' && i + 1 < n && text[i + 1] == '-'))
        ++i;
      tokens.push_back({text.substr(start, i - start), line, false});
    }
  }
  return tokens;
}

}  // namespace isovdb::reservoir
