// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file named_values.h
/// @brief The names of an enum's values as one table, in the order users read them:
///        value → name, name → value, and the "a, b or c" list every "unknown …,
///        expected …" message quotes, so a name and its messages cannot drift apart.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "isovdb/errors.h"

namespace isovdb {

template <typename Enum>
struct NamedValue {
  Enum value;
  std::string_view name;
};

template <typename Enum, std::size_t N>
using NameTable = std::array<NamedValue<Enum>, N>;

/// The name of `value`; "unknown" for a value the table lacks.
template <typename Enum, std::size_t N>
constexpr std::string_view nameOf(const NameTable<Enum, N>& table, Enum value) {
  for (const NamedValue<Enum>& entry : table)
    if (entry.value == value) return entry.name;
  return "unknown";
}

/// The value named `name`; std::nullopt for another name.
template <typename Enum, std::size_t N>
constexpr std::optional<Enum> valueNamed(const NameTable<Enum, N>& table, std::string_view name) {
  for (const NamedValue<Enum>& entry : table)
    if (entry.name == name) return entry.value;
  return std::nullopt;
}

/// The names as a message lists them: "a, b or c".
template <typename Enum, std::size_t N>
std::string nameList(const NameTable<Enum, N>& table) {
  std::string result;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) result += i + 1 == N ? " or " : ", ";
    result += table[i].name;
  }
  return result;
}

/// The value named `name`.
/// @param setting the flag or keyword that carried the name (`--method`, `method`).
/// @param what what a name stands for (`method`, `mode`).
/// @throw InputError "<setting>: unknown <what> '<name>', expected a, b or c".
template <typename Enum, std::size_t N>
Enum parseNamed(const NameTable<Enum, N>& table, std::string_view name, std::string_view setting,
                std::string_view what) {
  if (const std::optional<Enum> value = valueNamed(table, name)) return *value;
  throw InputError(std::string(setting) + ": unknown " + std::string(what) + " '" + std::string(name) + "', expected " +
                   nameList(table));
}

}  // namespace isovdb
