// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file errors.h
/// @brief The library's few exception types, derived from std types (as pmp does).
///
/// Every message is one line that a user can act on: it names the file (or
/// the argument), the field and what was expected.
#pragma once

#include <stdexcept>
#include <string>

namespace isovdb {

/// Bad input data or arguments: a file with a wrong header, a size that does
/// not match, a missing grid, an invalid option value.
struct InputError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// The operating system refused a read or a write (missing file, unwritable path).
struct IoError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A mesh or volume violates a topological guarantee that was required.
struct TopologyError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Long work was cancelled through an Interrupter; nothing half-built is returned.
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

}  // namespace isovdb
