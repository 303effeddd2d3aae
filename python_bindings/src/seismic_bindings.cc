// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// read_segy: the seismic front end (SEG-Y amplitude cubes).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.h"
#include "volume_bindings.h"

namespace isovdb::python {

namespace {

PyVolume readSegy(const std::filesystem::path& path, float clip, py::object mask, py::object maskRange,
                  py::object threshold, int inlineByte, int crosslineByte, bool sampleStatistics,
                  const py::object& progress) {
  const InputKeywords keywords{.threshold = std::move(threshold),
                               .labels = py::none(),
                               .mask = std::move(mask),
                               .maskRange = std::move(maskRange),
                               .clip = clip,
                               .inlineByte = inlineByte,
                               .crosslineByte = crosslineByte};
  pipeline::InputChoices choices = keywords.choices();
  choices.segy = true;
  pipeline::InputOptions options = pipeline::resolveInputChoices(path, choices);
  options.sampleStatistics = sampleStatistics;
  return loadWithProgress(path, options, progress);
}

}  // namespace

void bindSeismic(py::module_& m) {
  m.def("read_segy", &readSegy, py::arg("path"), py::kw_only(), py::arg("clip") = 0.f, py::arg("mask") = py::none(),
        py::arg("mask_range") = py::none(), py::arg("threshold") = py::none(), py::arg("inline_byte") = 189,
        py::arg("crossline_byte") = 193, py::arg("sample_statistics") = true, py::arg("progress") = py::none(),
        R"doc(
Reads a SEG-Y post-stack amplitude cube (any extension), trace by trace with segyio.

Grid axes: x = inline index, y = crossline index (at their CDP spacing), z = sample
(time in ms): to_numpy()[i] is inline i as a (crossline, sample) image. Holes (missing
traces) stay inactive. Without a mask rule the volume is the amplitude field (kind
"scalar"; contour it with extract(iso=amplitude)).

clip: samples with |amplitude| < clip stay inactive, the background is clip (a quiet cube
  costs little); extract() then needs |iso| >= clip.
mask="above A" | "below A", mask_range=(lo, hi), threshold=T (value > T): a binary mask instead.
inline_byte, crossline_byte: trace header bytes of the line numbers (SEG-Y rev 1: 189, 193).
sample_statistics: record the amplitudes' range and percentiles (info()["input"]["samples"]).
progress: callable(stage, percent); raising cancels and propagates.

info()["input"]["segy"] holds the survey geometry (sorting, line ranges and spacings,
sample interval, CDP origin and rotation). Raises OSError for a missing file and
ValueError for a file that is not valid SEG-Y (message names the file and the problem).)doc");
}

}  // namespace isovdb::python
