// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "setting_keywords.h"

#include <pybind11/eval.h>

#include <regex>
#include <sstream>
#include <type_traits>

#include "isovdb/errors.h"

namespace isovdb::python {

namespace {

template <typename T>
const char* typeName() {
  if constexpr (std::is_same_v<T, bool>)
    return "a bool";
  else if constexpr (std::is_same_v<T, int>)
    return "an int";
  else if constexpr (std::is_same_v<T, std::string>)
    return "a str";
  else if constexpr (std::is_same_v<T, std::optional<float>>)
    return "a number or None";
  else
    return "a number";
}

/// A flag's Python keyword: its name with '_' for '-', except where Python's differs.
std::string keywordOfFlag(const std::string& flag) {
  if (flag == "type") return "dtype";  // read_volume(dtype=...) is --type
  return pipeline::keywordOf(flag);
}

/// The current value of a setting as Python source (`0.15`, `True`, `'vdb'`): numbers as
/// the CLI's --help shows them, so that both front ends print the same default.
std::string pythonSource(const pipeline::Setting& setting) {
  std::ostringstream out;
  std::visit(
      [&out](auto* value) {
        using T = std::remove_pointer_t<decltype(value)>;
        if constexpr (std::is_same_v<T, bool>)
          out << (*value ? "True" : "False");
        else if constexpr (std::is_same_v<T, std::string>)
          out << py::repr(py::str(*value)).cast<std::string>();
        else if constexpr (std::is_same_v<T, std::optional<float>>) {
          if (*value)
            out << **value;
          else
            out << "None";
        } else
          out << *value;
      },
      setting.value);
  return out.str();
}

/// `text` wrapped at 88 columns, every line after the first indented by `indent`.
std::string wrapped(const std::string& text, const std::string& indent) {
  std::istringstream words(text);
  std::string word, result, line;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > 88) {
      result += line + "\n";
      line = indent;
    } else if (!line.empty() && line != indent) {
      line += " ";
    }
    line += word;
  }
  return result + line;
}

}  // namespace

std::string inPythonTerms(std::string_view message) {
  static const std::regex flag("(^|[\\s('\"])--([a-z][a-z-]*)");
  std::string text(message), result;
  auto last = text.cbegin();
  for (std::sregex_iterator it(text.begin(), text.end(), flag), end; it != end; ++it) {
    result.append(last, (*it)[2].first - 2);
    result += keywordOfFlag((*it)[2].str());
    last = (*it)[0].second;
  }
  result.append(last, text.cend());
  return result;
}

void assignSettings(const std::vector<pipeline::Setting>& settings, const py::dict& values) {
  for (const pipeline::Setting& setting : settings) {
    const std::string keyword = pipeline::keywordOf(setting.name);
    if (!values.contains(keyword)) continue;
    const py::object value = values[keyword.c_str()];
    if (value.is_none()) continue;
    std::visit(
        [&](auto* field) {
          using T = std::remove_pointer_t<decltype(field)>;
          // A bool is an int to Python; it is not a count or a size here.
          const bool isBool = py::isinstance<py::bool_>(value);
          bool ok = std::is_same_v<T, bool> == isBool;
          if constexpr (std::is_same_v<T, std::string>) ok = py::isinstance<py::str>(value);
          if constexpr (std::is_same_v<T, int>) ok = ok && py::isinstance<py::int_>(value);
          if (ok) {
            try {
              if constexpr (std::is_same_v<T, std::optional<float>>)
                *field = value.cast<float>();
              else
                *field = value.cast<T>();
              return;
            } catch (const py::cast_error&) {
            }
          }
          throw py::type_error(keyword + ": expected " + typeName<T>() + ", got " +
                               py::repr(value).cast<std::string>());
        },
        setting.value);
  }
}

void defineSettingsFunction(py::module_& m, const std::string& name, const std::string& implementation,
                            const std::vector<pipeline::Setting>& settings, const std::vector<ExtraKeyword>& extras,
                            const std::string& summary) {
  std::string parameters = "volume, *", values, forwarded;
  std::string doc = summary + "\n\nSettings (each the CLI flag --name, with '-' for '_'; None: the default):\n";
  for (const pipeline::Setting& setting : settings) {
    const std::string keyword = pipeline::keywordOf(setting.name);
    const std::string fallback = pythonSource(setting);
    parameters += ", " + keyword + "=" + fallback;
    values += "'" + keyword + "': " + keyword + ", ";
    doc += wrapped(keyword + " (" + fallback + "): " + inPythonTerms(setting.help), "    ") + "\n";
  }
  doc += "\n";
  for (const ExtraKeyword& extra : extras) {
    parameters += ", " + extra.name + "=" + extra.defaultSource;
    forwarded += ", " + extra.name + "=" + extra.name;
    doc += extra.help + "\n";
  }
  // A numpy array stands for from_numpy(array, <the array keywords>), as in scikit-image and
  // PyVista, and a pyopenvdb grid for from_openvdb(grid) (_as_volume, volume_bindings.cc).
  parameters += ", spacing=None, origin=None, kind=None, threshold=None";
  doc +=
      "spacing, origin, kind, threshold: for a numpy array, as from_numpy() takes them (spacing: one\n"
      "  voxel size or three, world units; origin: the world position of element [0, 0, 0]; kind: None\n"
      "  (by dtype), 'mask', 'field' or 'distance'; threshold: a mask of the values above it). A Volume\n"
      "  keeps its own: giving them with one raises ValueError.\n";
  const std::string source = "def " + name + "(" + parameters + "):\n    volume = _as_volume(volume, '" + name +
                             "', spacing=spacing, origin=origin, kind=kind, threshold=threshold)\n"
                             "    return " +
                             implementation + "(volume, {" + values + "}" + forwarded + ")\n";
  py::exec(source, m.attr("__dict__"));
  py::object function = m.attr(name.c_str());
  function.attr("__doc__") = doc;
  function.attr("__module__") = m.attr("__name__");
}

}  // namespace isovdb::python
