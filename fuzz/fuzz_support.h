// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file fuzz_support.h
/// @brief What every libFuzzer harness of fuzz/ shares: the input as a file (the
///        readers take paths, as the CLI hands them) and the rule for a finding.
///
/// A reader may reject its input only with the library's own exceptions
/// (InputError, IoError, TopologyError: the CLI's exit 1 or 2 with a one-line
/// message). Anything else escaping it is what the CLI reports as an internal
/// error (exit 3) and is a finding: libFuzzer stops on the uncaught exception, as
/// it does on a sanitizer report, a crash, a timeout or an allocation beyond
/// -malloc_limit_mb.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "isovdb/errors.h"

namespace isovdb::fuzz {

/// Writes the input to this process's scratch file named `input<extension>` (one per
/// extension, overwritten by each run, removed at exit) and returns its path.
std::filesystem::path writeInput(const std::uint8_t* data, std::size_t size, std::string_view extension);

/// Runs `read`; the library's rejections of bad input are expected outcomes.
template <class Read>
void expectCleanOutcome(Read&& read) {
  try {
    read();
  } catch (const InputError&) {
  } catch (const IoError&) {
  } catch (const TopologyError&) {
  }
}

}  // namespace isovdb::fuzz
