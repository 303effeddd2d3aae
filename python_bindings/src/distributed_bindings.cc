// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// The two halves of isovdb.distributed: what one Dask task runs on its slab of meta-cell
// layers (_extract_slab: pieces as bytes) and what the client runs with them
// (_extract_assembled: the pieces in order, stitched and streamed into the output file).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.h"
#include "isovdb/pipeline/extract.h"
#include "isovdb/pipeline/extract_settings.h"
#include "isovdb/pipeline/extract_to_file.h"
#include "isovdb/pipeline/meta_cell_pieces.h"
#include "isovdb/volume/sampled_box.h"
#include "progress_callback.h"
#include "setting_keywords.h"

namespace isovdb::python {

namespace {

pipeline::ExtractOptions optionsOf(const py::dict& settings) {
  pipeline::ExtractChoices choices;
  assignSettings(pipeline::extractSettings(choices), settings);
  return choices.resolve(/*keywords=*/true);
}

/// A task: the meta-cells of layers [begin, end) of `volume` (a slab read with its halo),
/// as bytes, and the task's figures (timings, meta-cells, bytes of mesh and of seams).
/// `valueRange`: a scalar field's whole range (_value_range of the first pass).
py::tuple extractSlab(const PyVolume& volume, const py::dict& settings, const std::array<int, 2>& layers,
                      const std::optional<std::pair<float, float>>& valueRange) {
  const pipeline::ExtractOptions options = optionsOf(settings);
  pipeline::MetaCellPieces pieces;
  pipeline::ExtractPart part;
  part.layers = pipeline::MetaCellLayers{layers[0], layers[1]};
  part.pieces = &pieces;
  part.valueRange = valueRange;
  pipeline::Statistics stats;
  mesh::MeshCollector nothing;  // a task's meshes all go to the pieces
  CallbackProgress callback{py::none()};
  callback.run([&] { pipeline::extractInto(volume.volume, options, nothing, &callback, &stats, &part); });
  Json& figures = stats["slab"];
  figures["layers"] = layers;
  figures["meta_cells"] = pieces.count();
  figures["bytes"] = pieces.bytes().size();
  figures["seam_bytes"] = pieces.seamBytes();
  std::string bytes = pieces.release();
  return py::make_tuple(py::bytes(bytes), toPython(stats.json()));
}

/// The client: `header` (the file read through an empty window) gives the index space,
/// geometry and box; `pieces` yields each task's bytes in slab order.
py::object extractAssembled(const PyVolume& header, const py::dict& settings, const std::filesystem::path& output,
                            const py::iterable& pieces, const py::object& progress,
                            const std::optional<std::pair<float, float>>& valueRange) {
  const pipeline::ExtractOptions options = optionsOf(settings);
  py::iterator next = py::iter(pieces);
  std::optional<py::bytes> held;  // the slab being read (its bytes stay alive while read)
  std::optional<pipeline::MetaCellPieceReader> reader;
  int slab = 0;
  pipeline::ExtractPart part;
  part.valueRange = valueRange;
  part.received = [&](volume::MetaCellIndex& index, contour::MetaCellMesh& block) {
    for (;;) {
      if (reader && reader->next(index, block)) return true;
      const py::gil_scoped_acquire gil;
      reader.reset();
      held.reset();
      if (next == py::iterator::sentinel()) return false;
      held = py::reinterpret_borrow<py::bytes>(*next);
      ++next;
      const std::string_view bytes = *held;  // the bytes object keeps them alive
      reader.emplace(bytes, "slab " + std::to_string(slab++));
    }
  };
  CallbackProgress callback(progress);
  pipeline::Statistics stats;
  callback.run([&] { pipeline::extractToFile(header.volume, options, output, &callback, &stats, &part); });
  {
    // The last bytes object is released with the GIL.
    reader.reset();
    held.reset();
  }
  stats["output"]["path"] = output.string();
  stats["slabs"] = slab;
  return toPython(stats.json());
}

/// A slab's samples for a scalar field's first pass: (active count, min, max, background).
py::tuple sampleRange(const PyVolume& volume) {
  const pipeline::SampleRange r = pipeline::sampleRangeOf(volume.volume);
  return py::make_tuple(r.active, r.min, r.max, r.background);
}

/// The whole field's value range from every slab's sampleRange (`header`: its sampled box).
std::pair<float, float> valueRange(const PyVolume& header, const std::vector<py::tuple>& slabs) {
  pipeline::SampleRange total;
  for (const py::tuple& t : slabs) {
    const pipeline::SampleRange r{.active = t[0].cast<std::int64_t>(),
                                  .min = t[1].cast<float>(),
                                  .max = t[2].cast<float>(),
                                  .background = t[3].cast<float>()};
    total.background = r.background;
    total += r;
  }
  return pipeline::valueRangeOf(total, volume::sampledBox(header.volume));
}

}  // namespace

void bindDistributed(py::module_& m) {
  m.def("_sample_range", &sampleRange, py::arg("volume"),
        "A slab's (active samples, min, max, background): a scalar field's first pass.");
  m.def("_value_range", &valueRange, py::arg("header"), py::arg("slabs"),
        "The whole field's value range from every slab's _sample_range.");
  m.def("_extract_slab", &extractSlab, py::arg("volume"), py::arg("settings"), py::arg("layers"),
        py::arg("value_range") = py::none(),
        "isovdb.distributed's task: the meta-cells of layers [begin, end) of a slab Volume (read with window= "
        "and _slab_halo's halo), as (bytes, figures).");
  m.def("_extract_assembled", &extractAssembled, py::arg("header"), py::arg("settings"), py::arg("output"),
        py::arg("pieces"), py::arg("progress") = py::none(), py::arg("value_range") = py::none(),
        "isovdb.distributed's client: every slab's bytes in order, stitched and written to output (.ply).");
  m.def(
      "_slab_halo", [](const py::dict& settings) { return pipeline::slabHalo(optionsOf(settings)); },
      py::arg("settings"), "Voxels a slab task reads beyond its layers (its samples are then the whole volume's).");
}

}  // namespace isovdb::python
