// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// extract: any volume -> Mesh, its keywords the settings table of `isovdb extract`.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <regex>
#include <sstream>
#include <string>

#include "bindings.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/extract_settings.h"
#include "isovdb/pipeline/extract_to_file.h"
#include "progress_callback.h"
#include "setting_keywords.h"

namespace isovdb::python {

namespace {

/// scikit-image raises where no surface is found, so extract() does too (the CLI writes the
/// empty mesh: batch runs over labels expect a file). Names what the volume holds.
std::string noSurfaceMessage(const volume::Volume& volume, pipeline::Statistics& stats) {
  const volume::GridStats grid = volume.stats();
  std::ostringstream message;
  message << "no surface: ";
  switch (volume.kind()) {
    case volume::VolumeKind::Mask:
      message << (grid.activeVoxels == 0 ? "the mask has no voxel inside" : "the mask meets no surface");
      break;
    case volume::VolumeKind::DistanceField:
      message << "the distance field has no sign change (values in [" << grid.minValue << ", " << grid.maxValue << "])";
      break;
    case volume::VolumeKind::Scalar:
      message << "the field never crosses iso " << stats.json()["contour"].value("iso", 0.0) << " (values in ["
              << grid.minValue << ", " << grid.maxValue << "])";
      break;
  }
  message << ", so the mesh would be empty";
  return message.str();
}

/// `message` with the word "iso" named "level", for a caller who gave level=.
std::string withLevel(const std::string& message) {
  static const std::regex iso(R"(\biso\b)");
  return std::regex_replace(message, iso, "level");
}

py::object extractWith(const PyVolume& volume, const py::dict& settings, const py::object& progress,
                       const std::optional<std::filesystem::path>& output, const py::object& level) {
  pipeline::ExtractChoices choices;
  assignSettings(pipeline::extractSettings(choices), settings);
  if (!level.is_none()) {
    if (choices.options.iso) throw py::value_error("give iso= or level= (the same setting), not both");
    assignSettings(pipeline::extractSettings(choices), py::dict(py::arg("iso") = level));
  }
  const pipeline::ExtractOptions options = choices.resolve(/*keywords=*/true);
  CallbackProgress callback(progress);
  pipeline::Statistics stats;
  if (output) {
    callback.run([&] { pipeline::extractToFile(volume.volume, options, *output, &callback, &stats); });
    stats["output"]["path"] = output->string();
    return toPython(stats.json());
  }
  PyMesh result;
  callback.run([&] { result.mesh = pipeline::extractMesh(volume.volume, options, &callback, &stats); });
  if (result.mesh.triangles.empty()) throw py::value_error(noSurfaceMessage(volume.volume, stats));
  result.statistics = std::move(stats.json());
  return py::cast(std::move(result));
}

py::object extract(const PyVolume& volume, const py::dict& settings, const py::object& progress,
                   const std::optional<std::filesystem::path>& output, const py::object& level) {
  if (level.is_none()) return extractWith(volume, settings, progress, output, level);
  // The messages name the setting iso; a caller who wrote level= reads level.
  if (settings.contains("iso") && !settings["iso"].is_none())
    throw py::value_error("give iso= or level= (the same setting), not both");
  try {
    return extractWith(volume, settings, progress, output, level);
  } catch (const InputError& e) {
    throw InputError(withLevel(e.what()));
  } catch (const py::value_error& e) {
    throw py::value_error(withLevel(e.what()));
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError)) throw;
    throw py::value_error(withLevel(py::str(e.value()).cast<std::string>()));
  }
}

}  // namespace

void bindExtract(py::module_& m) {
  m.def("_extract", &extract, py::arg("volume"), py::arg("settings"), py::kw_only(), py::arg("progress"),
        py::arg("output"), py::arg("level"), "extract()'s implementation: the settings as a dict of keywords.");
  pipeline::ExtractChoices defaults;
  defineSettingsFunction(m, "extract", "_extract", pipeline::extractSettings(defaults),
                         {{"progress", "None",
                           "progress: callable(stage: str, percent: int), called from worker threads (with the GIL)\n"
                           "  whenever a stage's percentage changes. If it raises, the work is cancelled and the\n"
                           "  exception propagates; nothing is returned. Ctrl-C (KeyboardInterrupt, Jupyter's\n"
                           "  \"interrupt kernel\") cancels the same way, with or without a callback."},
                          {"output", "None",
                           "output: None (return a Mesh), or a .ply/.obj/.stl/.glb path: write the mesh there as\n"
                           "  `isovdb extract -o PATH` does (the octree methods stream a .ply meta-cell by meta-cell,\n"
                           "  never holding the mesh; same bytes as the CLI) and return the run's statistics dict.\n\n"
                           "The GIL is released while contouring. Mesh.statistics holds the run's figures.\n"
                           "Raises ValueError for an invalid setting, a scalar iso inside a clipped dead band or\n"
                           "a volume without a surface (an empty mask: the mesh would be empty; with output=, the\n"
                           "empty mesh is written, as the CLI does),\n"
                           "TypeError for a setting of the wrong type."},
                          {"level", "None", "level: scikit-image's name for iso (give one, not both)."}},
                         "Contours a volume into a closed triangle Mesh in world space (the `isovdb extract` job).\n\n"
                         "volume: a mask (its distance field is computed first), a distance field (from\n"
                         "distance_field() or a level-set .vdb) or a scalar field (from_numpy of floats, SEG-Y);\n"
                         "a 3-D numpy array is read by from_numpy(array) first.\n"
                         "Every setting is the CLI flag of the same name with the same default: method='adaptive'\n"
                         "(closed, manifold, free of self-intersections, on the data boundary's caps too, a\n"
                         "mask's topology, far\n"
                         "fewer triangles; within max_error=1 voxel of the full-resolution surface), 'regular'\n"
                         "(the mask's topology, closed, manifold, free of self-intersections, caps included)\n"
                         "or 'vdb' (OpenVDB's\n"
                         "volumeToMesh, the reference).");
}

}  // namespace isovdb::python
