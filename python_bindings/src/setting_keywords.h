// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file setting_keywords.h
/// @brief Python functions whose keywords are a table of settings (pipeline/extract_settings.h):
///        the signature, the defaults and the docstring come from the table the CLI's flags
///        come from, so `help(isovdb.extract)` and `isovdb extract --help` cannot disagree.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "bindings.h"
#include "isovdb/pipeline/extract_settings.h"

namespace isovdb::python {

/// A library message in Python's terms: each CLI flag (`--meta-cell`, `--type`) named as the
/// keyword Python takes (`meta_cell`, `dtype`). Flags are recognised at the start of the
/// text or after a space, quote or parenthesis, so a file name holding "--" is kept.
std::string inPythonTerms(std::string_view message);

/// Stores each keyword of `values` in the setting it names; None keeps the setting's default.
/// @throw InputError naming the keyword when a value has the wrong type.
void assignSettings(const std::vector<pipeline::Setting>& settings, const py::dict& values);

/// A keyword after the settings that is not one of them: its name, its default as Python
/// source and its line of documentation.
struct ExtraKeyword {
  std::string name, defaultSource, help;
};

/// Defines `m.name(volume, *, <the settings>, <the extras>)` as a Python function (so that
/// inspect.signature lists every keyword with its default) that calls
/// `m.implementation(volume, {setting keyword: value}, <extra>=<extra>, ...)`.
/// The docstring is `summary`, the settings with their defaults and help, then the extras.
void defineSettingsFunction(py::module_& m, const std::string& name, const std::string& implementation,
                            const std::vector<pipeline::Setting>& settings, const std::vector<ExtraKeyword>& extras,
                            const std::string& summary);

}  // namespace isovdb::python
