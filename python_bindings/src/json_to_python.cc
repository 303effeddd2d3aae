// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "bindings.h"

#include <pybind11/stl.h>

#include "isovdb/errors.h"

namespace isovdb::python {

py::object toPython(const Json& json) {
  switch (json.type()) {
    case Json::value_t::object: {
      py::dict dict;
      for (const auto& [key, value] : json.items()) dict[py::str(key)] = toPython(value);
      return dict;
    }
    case Json::value_t::array: {
      py::list list;
      for (const auto& value : json) list.append(toPython(value));
      return list;
    }
    case Json::value_t::string:
      return py::str(json.get<std::string>());
    case Json::value_t::boolean:
      return py::bool_(json.get<bool>());
    case Json::value_t::number_integer:
      return py::int_(json.get<std::int64_t>());
    case Json::value_t::number_unsigned:
      return py::int_(json.get<std::uint64_t>());
    case Json::value_t::number_float:
      return py::float_(json.get<double>());
    default:
      return py::none();
  }
}

std::array<double, 3> threeDoubles(const py::object& value, const char* name) {
  try {
    if (py::isinstance<py::sequence>(value) && !py::isinstance<py::str>(value)) {
      const auto values = value.cast<std::vector<double>>();
      if (values.size() == 3) return {values[0], values[1], values[2]};
    } else {
      const double v = value.cast<double>();
      return {v, v, v};
    }
  } catch (const py::cast_error&) {
  }
  throw py::value_error(std::string(name) + ": expected a number or a sequence of three numbers, got " +
                        py::repr(value).cast<std::string>());
}

}  // namespace isovdb::python
