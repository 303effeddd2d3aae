// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file grdecl_tokens.h
/// @brief Splits Eclipse GRDECL text into tokens: `--` comments dropped,
/// quoted strings kept whole, `/` record terminators as their own token.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace isovdb::reservoir {

/// A token views the file's text (which the caller keeps while it reads them): a deck of
/// 10^7 numbers made as many strings, most of the reading's time and memory.
struct GrdeclToken {
  std::string_view text;  ///< without quotes for a quoted string
  int line = 0;           ///< 1-based line in the file
  bool quoted = false;
  bool isSlash() const { return !quoted && text == "/"; }
};

/// Tokens of one file's text in order, viewing `text`. `/` glued to a value ("0.3/") is split off.
std::vector<GrdeclToken> tokenizeGrdecl(std::string_view text);

}  // namespace isovdb::reservoir
