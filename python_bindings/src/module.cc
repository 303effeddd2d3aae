// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// The `isovdb` Python module: exceptions, then one registration per topic.
#include <dlfcn.h>
#include <pybind11/pybind11.h>

#include <filesystem>
#include <string>

#include "bindings.h"
#include "setting_keywords.h"
#include "isovdb/errors.h"
#include "isovdb/pipeline/memory.h"

namespace py = pybind11;

namespace {

/// The folder of the module's pure-Python submodules (isovdb.distributed): isovdb-modules/
/// beside the extension's own file, found from this code's address (the module's
/// __file__ is set only after its initialisation).
std::string submoduleFolder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&submoduleFolder), &info) == 0 || !info.dli_fname) return {};
  return (std::filesystem::path(info.dli_fname).parent_path() / "isovdb-modules").string();
}

}  // namespace

PYBIND11_MODULE(isovdb, m) {
  isovdb::pipeline::keepFreedHeapMemory();
  m.doc() =
      "isovdb: sparse volumes to clean triangle meshes.\n\n"
      "Volumes (binary masks, scalar fields, signed distance fields) come from files\n"
      "(read_volume, read_segy), numpy arrays (from_numpy) or sparse slice stacks\n"
      "(morph_slices); distance_field() turns a mask into a narrow-band signed distance\n"
      "field; extract() contours any volume into a Mesh whose vertices/triangles are\n"
      "numpy views. Arrays are indexed [x, y, z]. extract_reservoir() contours a\n"
      "property of an Eclipse corner-point grid (GRDECL).\n\n"
      "Errors: bad input raises ValueError, an unreadable or unwritable file OSError,\n"
      "both with the library's one-line message naming the file and the problem.";
  m.attr("__version__") = "0.1.0";
  // A package's search path: `import isovdb.distributed` finds distributed.py there.
  py::list path;
  path.append(submoduleFolder());
  m.attr("__path__") = path;

  static py::exception<isovdb::Interrupted> interrupted(m, "Interrupted", PyExc_RuntimeError);
  interrupted.doc() = "Long work was cancelled through its progress callback.";
  static py::exception<isovdb::TopologyError> topology(m, "TopologyError", PyExc_RuntimeError);
  topology.doc() = "A mesh or volume violates a topological guarantee that was required.";
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const isovdb::InputError& e) {
      PyErr_SetString(PyExc_ValueError, isovdb::python::inPythonTerms(e.what()).c_str());
    } catch (const isovdb::IoError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const isovdb::Interrupted& e) {
      PyErr_SetString(interrupted.ptr(), e.what());
    } catch (const isovdb::TopologyError& e) {
      PyErr_SetString(topology.ptr(), e.what());
    }
  });

  isovdb::python::bindVolume(m);
  isovdb::python::bindSeismic(m);
  isovdb::python::bindMesh(m);
  isovdb::python::bindExtract(m);
  isovdb::python::bindMorph(m);
  isovdb::python::bindReservoir(m);
  isovdb::python::bindDistributed(m);
  isovdb::python::nameWrongArguments(m);
}
