// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// morph_slices: the slice-stack front end (level-set metamorphosis between sparse slices).
#include <tbb/global_control.h>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "bindings.h"
#include "isovdb/errors.h"
#include "isovdb/morph/reconstruct.h"
#include "isovdb/morph/reconstruction_report.h"
#include "isovdb/morph/slice_stack.h"
#include "progress_callback.h"

namespace isovdb::python {

namespace {

/// A folder of slice images (with heights or a spacing), or a mask volume with labelled z-slices.
morph::SliceStack sliceStackOf(const py::object& slices, const std::optional<std::filesystem::path>& heights,
                               std::optional<double> spacing, double pixelSize, int sliceStep, int sliceOffset) {
  if (py::isinstance<PyVolume>(slices)) {
    if (heights || spacing)
      throw InputError(
          "morph_slices: heights and spacing apply to a folder of slice images; a volume's heights "
          "are its z positions");
    return morph::sliceStackFromVolume(slices.cast<const PyVolume&>().volume,
                                       {.step = sliceStep, .offset = sliceOffset});
  }
  const auto dir = slices.cast<std::filesystem::path>();
  return morph::loadSliceDirectory(dir, {.heightsFile = heights.value_or(std::filesystem::path()),
                                         .spacing = spacing.value_or(0.0),
                                         .pixelSize = pixelSize});
}

PyVolume morphSlices(const py::object& slices, const std::optional<std::filesystem::path>& heights,
                     std::optional<double> spacing, double pixelSize, int sliceStep, int sliceOffset,
                     std::optional<double> zStep, const std::string& interpolate, const std::string& progressMode,
                     bool pls, bool centring, bool areaMatch, double tolerance, int maxIterations, float halfWidth,
                     std::optional<int> threads, const py::object& progress) {
  morph::ReconstructOptions options;
  options.pair.interpolation = parseNamed(morph::kInterpolationNames, interpolate, "interpolate", "interpolation");
  options.pair.progress = parseNamed(morph::kProgressNames, progressMode, "progress_mode", "progress mode");
  options.pair.particles = pls;
  options.pair.centre = centring;
  options.pair.matchArea = areaMatch;
  options.pair.evolution.tolerance = tolerance;
  options.pair.evolution.maxIterations = maxIterations;
  options.halfWidth = halfWidth;
  morph::checkReconstructOptions(options);
  morph::SliceStack stack = sliceStackOf(slices, heights, spacing, pixelSize, sliceStep, sliceOffset);
  if (zStep) stack.zStep = *zStep;

  CallbackProgress callback(progress);
  PyVolume result;
  callback.run([&] {
    std::unique_ptr<tbb::global_control> limit;
    if (threads && *threads > 0)
      limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, *threads);
    const morph::Reconstruction r = morph::reconstruct(stack, options, &callback);
    result.volume = r.volume;
    result.input = morph::reconstructionReport(r, options);
  });
  result.input["slices"] = stack.slices.size();
  result.input["canvas"] = std::to_string(stack.width) + "x" + std::to_string(stack.height);
  return result;
}

}  // namespace

void bindMorph(py::module_& m) {
  const morph::ReconstructOptions defaults;
  m.def("morph_slices", &morphSlices, py::arg("slices"), py::kw_only(), py::arg("heights") = py::none(),
        py::arg("spacing") = py::none(), py::arg("pixel_size") = 1.0, py::arg("slice_step") = 0,
        py::arg("slice_offset") = 0, py::arg("z_step") = py::none(),
        py::arg("interpolate") = std::string(morph::interpolationName(defaults.pair.interpolation)),
        py::arg("progress_mode") = std::string(morph::progressName(defaults.pair.progress)),
        py::arg("pls") = defaults.pair.particles, py::arg("centring") = defaults.pair.centre,
        py::arg("area_match") = defaults.pair.matchArea, py::arg("tolerance") = defaults.pair.evolution.tolerance,
        py::arg("max_iterations") = defaults.pair.evolution.maxIterations, py::arg("half_width") = defaults.halfWidth,
        py::arg("threads") = py::none(), py::arg("progress") = py::none(), R"doc(
Completes a sparse stack of parallel slices by level-set metamorphosis (the `isovdb morph`
job, paper 002) and returns the completed stack as a distance-field Volume; contour it
with extract().

slices: a folder of PNG/BMP slice images (filled regions or thin closed contours; a contour
  inside a contour is a hole) with heights=path of a text file (one height per image, in
  name order) or spacing=DZ; or a mask Volume whose labelled z-slices are the slices
  (slice_step=K, slice_offset=O: z = O + k K; 0 = every non-empty z-slice).
pixel_size: world units per pixel (folders). z_step: world units between the output planes
  (default: the pixel size / the volume's z spacing).
interpolate: "levelset" (metamorphosis), "nearest" (copy the nearer slice) or "linear"
  (shape-based: blend of the two signed distances).
progress_mode: which iterate each intermediate slice shows: "exponential" (time of arrival
  from the exponential approach), "arrival" (measured per pixel) or "iterations" (the paper's).
pls: particle level set correction (levelset only). centring: centre both contours on their
  convex-hull centroids first when that makes them overlap more (one moving object), else
  morph them in place. area_match: give each intermediate slice the linear blend of the two
  originals' areas (one offset of its distance; the morph alone shrinks moving sections and
  caps). tolerance, max_iterations: convergence (eq. 3.13), per pair.
half_width: narrow band of the output distance field (voxels).
threads: worker threads (None = every core); the result is the same.
progress: callable(stage, percent); raising cancels and propagates.

info()["input"] holds the figures of the reconstruction (slices, planes, iterations, per-pair
figures, seconds per intermediate slice). Raises OSError for a missing folder and ValueError
for bad slices or options (the message names the file or the keyword).)doc");
}

}  // namespace isovdb::python
