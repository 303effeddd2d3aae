// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
// Volume, from_numpy, read_volume, distance_field.
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>

#include "array_slice_stream.h"
#include "bindings.h"
#include "isovdb/errors.h"
#include "isovdb/io/slice_window.h"
#include "isovdb/store/dense_array.h"
#include "isovdb/store/dense_writer.h"
#include "isovdb/store/vdb_file.h"
#include "isovdb/pipeline/input_choices.h"
#include "isovdb/pipeline/load_volume.h"
#include "isovdb/pipeline/write_distance_field.h"
#include "isovdb/volume/digital_topology.h"
#include "isovdb/volume/distance_field.h"
#include "isovdb/volume/ingest.h"
#include "isovdb/volume/sampled_box.h"
#include "progress_callback.h"
#include "setting_keywords.h"
#include "volume_bindings.h"

namespace isovdb::python {

namespace {

/// The library's sample type of a numpy dtype, or a ValueError naming the dtype.
io::SampleType sampleTypeOf(const py::dtype& dtype) {
  const char kind = dtype.kind();
  const auto size = dtype.itemsize();
  if (kind == 'b') return io::SampleType::UInt8;
  if (kind == 'u' && size == 1) return io::SampleType::UInt8;
  if (kind == 'u' && size == 2) return io::SampleType::UInt16;
  if (kind == 'u' && size == 4) return io::SampleType::UInt32;
  if (kind == 'i' && size == 1) return io::SampleType::Int8;
  if (kind == 'i' && size == 2) return io::SampleType::Int16;
  if (kind == 'i' && size == 4) return io::SampleType::Int32;
  if (kind == 'f' && size == 4) return io::SampleType::Float32;
  if (kind == 'f' && size == 8) return io::SampleType::Float64;
  throw py::value_error("from_numpy: unsupported dtype " + py::str(static_cast<py::handle>(dtype)).cast<std::string>() +
                        ", expected bool, (u)int8, (u)int16, (u)int32, (u)int64 (values within int32), float16, "
                        "float32 or float64");
}

/// The array itself, or a converted copy for the dtypes numpy hands out that the ingest does not
/// read: 64-bit integers (scipy.ndimage.label's labels) as int32 when their values fit, float16
/// as float32. Other dtypes stay (sampleTypeOf names them).
py::array withSupportedDtype(const py::array& array) {
  const char kind = array.dtype().kind();
  const auto size = array.dtype().itemsize();
  if ((kind == 'i' || kind == 'u') && size == 8) {
    // numpy's own scalars print the values: a uint64 beyond int64 is no long long.
    const py::object lo = array.attr("min")(), hi = array.attr("max")();
    if (lo.cast<double>() < -2147483648.0 || hi.cast<double>() > 2147483647.0)
      throw py::value_error("from_numpy: " + py::str(static_cast<py::handle>(array.dtype())).cast<std::string>() +
                            " values in [" + py::str(lo).cast<std::string>() + ", " + py::str(hi).cast<std::string>() +
                            "] do not fit in int32; pass a.astype(numpy.float64) to read them as a scalar field");
    return array.attr("astype")("int32");
  }
  if (kind == 'f' && size == 2) return array.attr("astype")("float32");
  return array;
}

std::string shapeText(const py::array& array) {
  return py::str(py::tuple(py::cast(std::vector<py::ssize_t>(array.shape(), array.shape() + array.ndim()))))
      .cast<std::string>();
}

/// from_numpy(), and a slab of a larger array for a distributed run's task: `placement`
/// None, or (first, total): the array holds grid z slices [first, first + its depth) of a
/// volume of `total` slices (the others read as holes).
PyVolume fromNumpyPlaced(py::object object, const py::object& threshold, py::object voxelSize, const py::object& origin,
                         const py::object& spacingKeyword, const py::object& kindKeyword, const py::object& placement) {
  const std::string kind = kindKeyword.is_none() ? "" : py::str(kindKeyword).cast<std::string>();
  if (!kindKeyword.is_none() &&
      (!py::isinstance<py::str>(kindKeyword) || (kind != "mask" && kind != "field" && kind != "distance")))
    throw py::value_error("from_numpy: kind: expected None (by dtype), 'mask', 'field' or 'distance', got " +
                          py::repr(kindKeyword).cast<std::string>());
  if ((kind == "field" || kind == "distance") && !threshold.is_none())
    throw py::value_error("from_numpy: kind='" + kind + "' keeps the values; a threshold makes a mask (kind='mask')");
  // Messages name the keyword the caller used.
  const std::string sizeKeyword = spacingKeyword.is_none() ? "voxel_size" : "spacing";
  if (!spacingKeyword.is_none()) {
    if (!(py::isinstance<py::float_>(voxelSize) && voxelSize.cast<double>() == 1.0))
      throw py::value_error("from_numpy: give voxel_size= or spacing= (the same keyword), not both");
    voxelSize = spacingKeyword;
  }
  // Nested lists and tuples, as numpy.asarray reads them (scikit-image takes any array_like).
  if (py::isinstance<py::list>(object) || py::isinstance<py::tuple>(object))
    object = py::module_::import("numpy").attr("asarray")(object);
  if (!py::isinstance<py::array>(object))
    throw py::value_error("from_numpy: expected a numpy array, got " +
                          py::str(py::type::handle_of(object).attr("__name__")).cast<std::string>());
  auto array = py::reinterpret_borrow<py::array>(object);
  if (array.ndim() != 3)
    throw py::value_error("from_numpy: expected a 3-D array indexed [x, y, z], got a " + std::to_string(array.ndim()) +
                          "-D array of shape " + shapeText(array));
  // A placed slab may hold no slice (a window beyond the array: the header alone).
  if (array.size() == 0 && placement.is_none())
    throw py::value_error("from_numpy: empty array of shape " + shapeText(array));
  array = withSupportedDtype(array);
  const io::SampleType type = sampleTypeOf(array.dtype());
  // A [z, y, x] stack's transpose is Fortran-ordered: read as it lies (x fastest, like a raw
  // file). Any other layout (a strided slice) is copied into C order first.
  bool xFastest = !(array.flags() & py::array::c_style) && (array.flags() & py::array::f_style);
  if (!placement.is_none() && !xFastest) {
    // A placed slab is read in z-planes, the slices it is placed by.
    array = py::module_::import("numpy").attr("asfortranarray")(array);
    xFastest = true;
  }
  if (!(array.flags() & py::array::c_style) && !xFastest)
    array = py::module_::import("numpy").attr("ascontiguousarray")(array);
  const bool bigEndian = array.dtype().attr("byteorder").cast<std::string>() == ">";
  const std::array<double, 3> spacing = threeDoubles(voxelSize, sizeKeyword.c_str());
  for (double s : spacing)
    if (!(s > 0) || !std::isfinite(s)) throw py::value_error(sizeKeyword + ": expected finite values > 0");
  const std::array<double, 3> position = threeDoubles(origin, "origin");
  const bool scalar = kind == "field" || (kind.empty() && threshold.is_none() && io::isFloatingPoint(type));
  volume::MaskRule rule;
  if (!threshold.is_none()) rule.threshold = threshold.cast<double>();

  ArraySliceStream stream(static_cast<const std::byte*>(array.data()), {array.shape(0), array.shape(1), array.shape(2)},
                          type, bigEndian, spacing, position, xFastest);
  std::optional<io::PlacedSliceStream> placed;
  io::SliceStream* source = &stream;
  if (!placement.is_none()) {
    const auto where = placement.cast<std::array<std::int64_t, 2>>();
    source = &placed.emplace(stream, where[0], where[1]);
  }
  PyVolume result;
  {
    py::gil_scoped_release release;
    if (kind == "distance")
      result.volume = volume::ingestSignedDistances(*source);
    else
      result.volume = scalar ? volume::ingestScalar(*source) : volume::ingestMask(*source, rule);
  }
  Json& input = result.input;
  input["format"] = "numpy";
  input["dims"] = std::array<std::int64_t, 3>{array.shape(0), array.shape(1), array.shape(2)};
  input["dtype"] = py::str(static_cast<py::handle>(array.dtype())).cast<std::string>();
  if (!scalar && kind != "distance") input["mask_rule"] = rule.describe();
  return result;
}

PyVolume readVolume(const std::filesystem::path& path, const py::object& dims, const py::object& dtype, bool bigEndian,
                    const py::object& spacing, std::int64_t headerBytes, py::object threshold, py::object labels,
                    py::object mask, py::object maskRange, float clip, int inlineByte, int crosslineByte, bool scalar,
                    const std::string& grid, bool segy, bool sampleStatistics, const py::object& progress,
                    const py::object& window) {
  const InputKeywords keywords{.threshold = std::move(threshold),
                               .labels = std::move(labels),
                               .mask = std::move(mask),
                               .maskRange = std::move(maskRange),
                               .clip = clip,
                               .inlineByte = inlineByte,
                               .crosslineByte = crosslineByte};
  pipeline::InputChoices choices = keywords.choices();
  choices.scalar = scalar;
  choices.grid = grid;
  choices.segy = segy;
  if (!dims.is_none() || !dtype.is_none()) {
    if (dims.is_none() || dtype.is_none())
      throw py::value_error("'" + path.string() + "': a raw file needs both dims=(x, y, z) and dtype");
    const auto d = dims.cast<std::vector<std::int64_t>>();
    if (d.size() != 3) throw py::value_error("'" + path.string() + "': dims: expected (x, y, z)");
    const py::dtype type = py::dtype::from_args(dtype);
    io::RawOptions raw;
    raw.dims = {d[0], d[1], d[2]};
    raw.type = sampleTypeOf(type);
    raw.bigEndian = bigEndian || type.attr("byteorder").cast<std::string>() == ">";
    if (!spacing.is_none()) raw.spacing = threeDoubles(spacing, "spacing");
    raw.headerBytes = headerBytes;
    choices.raw = raw;
  }
  pipeline::InputOptions options = pipeline::resolveInputChoices(path, choices);
  options.sampleStatistics = sampleStatistics;
  if (!window.is_none()) {
    const auto range = window.cast<std::array<std::int64_t, 2>>();
    if (range[0] > range[1])
      throw py::value_error("window: expected (begin, end) with begin <= end, got (" + std::to_string(range[0]) + ", " +
                            std::to_string(range[1]) + ")");
    options.window = io::SliceWindow{range[0], range[1]};
  }
  return loadWithProgress(path, options, progress);
}

py::array toNumpy(const PyVolume& self, const py::object& bbox) {
  volume::IndexBox box;
  if (bbox.is_none()) {
    box = store::defaultDenseBox(self.volume);
  } else {
    const auto corners = bbox.cast<std::pair<std::array<int, 3>, std::array<int, 3>>>();
    box = {.min = corners.first, .max = corners.second};
  }
  std::vector<py::ssize_t> shape(3);
  for (int a = 0; a < 3; ++a) {
    shape[a] = static_cast<py::ssize_t>(box.max[a]) - box.min[a] + 1;
    if (shape[a] <= 0)
      throw py::value_error("to_numpy: empty box (min " + py::str(toTuple(box.min)).cast<std::string>() + ", max " +
                            py::str(toTuple(box.max)).cast<std::string>() + ")" +
                            (bbox.is_none() ? ": the volume has no active voxel" : ""));
  }
  if (self.volume.kind() == volume::VolumeKind::Mask) {
    py::array_t<bool> out(shape);
    bool* data = out.mutable_data();
    py::gil_scoped_release release;
    store::copyToDense(self.volume, box, data);
    return out;
  }
  py::array_t<float> out(shape);
  float* data = out.mutable_data();
  py::gil_scoped_release release;
  store::copyToDense(self.volume, box, data);
  return out;
}

py::dict info(const PyVolume& self) {
  Json json = Json::object();
  json["name"] = self.volume.name();
  pipeline::recordGridStats(self.volume, json);
  if (const auto box = volume::sampledBox(self.volume)) {
    json["sampled_min"] = box->min;
    json["sampled_max"] = box->max;
  }
  json["input"] = self.input;
  return toPython(json);
}

void write(const PyVolume& self, const std::filesystem::path& path, const std::string& gridName) {
  py::gil_scoped_release release;
  if (pipeline::isVdbPath(path))
    store::writeVdb(path, self.volume, {.gridName = gridName});
  else if (store::isDenseOutputPath(path))
    store::writeDenseVolume(path, self.volume);
  else
    throw InputError("'" + path.string() + "': unknown volume format, expected .vdb, .raw or .nrrd");
}

/// A temporary .vdb file for pickling, removed when this goes out of scope.
class TemporaryVdb {
 public:
  TemporaryVdb() {
    const py::tuple made = py::module_::import("tempfile").attr("mkstemp")(py::arg("suffix") = ".vdb");
    py::module_::import("os").attr("close")(made[0]);
    path_ = made[1].cast<std::string>();
  }
  TemporaryVdb(const TemporaryVdb&) = delete;
  TemporaryVdb& operator=(const TemporaryVdb&) = delete;
  ~TemporaryVdb() {
    std::error_code ignored;
    std::filesystem::remove(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// What pickle keeps of a Volume: the grid as .vdb bytes (metadata, sampled box and
/// transform included), its name and what reading it recorded.
py::tuple volumeState(const PyVolume& self) {
  const std::array<double, 3>& spacing = self.volume.geometry().spacing;
  if (self.volume.kind() == volume::VolumeKind::DistanceField && (spacing[0] != spacing[1] || spacing[0] != spacing[2]))
    throw InputError("Volume '" + self.volume.name() +
                     "' cannot be pickled: a distance field with a non-uniform voxel size (" +
                     py::str(toTuple(spacing)).cast<std::string>() + ") has no .vdb level-set form");
  const TemporaryVdb file;
  {
    py::gil_scoped_release release;
    store::writeVdb(file.path(), self.volume);
  }
  std::ifstream in(file.path(), std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return py::make_tuple(py::bytes(bytes), self.volume.name(), self.input.dump());
}

PyVolume volumeFromState(const py::tuple& state) {
  if (state.size() != 3)
    throw py::value_error("Volume: cannot unpickle a state of " + std::to_string(state.size()) + " items");
  const TemporaryVdb file;
  {
    std::ofstream out(file.path(), std::ios::binary);
    const std::string bytes = state[0].cast<std::string>();
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw IoError("Volume: cannot unpickle: '" + file.path().string() + "' could not be written");
  }
  volume::Volume read;
  {
    py::gil_scoped_release release;
    read = store::readVdb(file.path());
  }
  PyVolume result;
  result.volume = volume::Volume(read.kind(), read.grid(), read.geometry(), state[1].cast<std::string>());
  result.input = Json::parse(state[2].cast<std::string>());
  return result;
}

py::object distanceField(const PyVolume& source, const py::dict& settings, const py::object& progress,
                         const std::optional<std::filesystem::path>& output, const std::string& gridName) {
  pipeline::DistanceChoices choices;
  assignSettings(pipeline::distanceSettings(choices), settings);
  const volume::DistanceFieldOptions options = choices.resolve(/*keywords=*/true);
  CallbackProgress callback(progress);
  if (output) {  // `isovdb sdf`: streamed to the file, never held whole
    if (source.volume.kind() != volume::VolumeKind::Mask)
      throw InputError("'" + source.volume.name() + "': a distance field is made from a mask");
    pipeline::Statistics stats;
    callback.run(
        [&] { pipeline::writeDistanceFieldVdb(source.volume, options, *output, gridName, &callback, &stats); });
    stats["output"]["path"] = output->string();
    return toPython(stats.json());
  }
  PyVolume result;
  callback.run([&] { result.volume = volume::distanceField(source.volume, options, &callback); });
  result.input = source.input;
  result.input["distance_field"] = {{"method", std::string(volume::distanceMethodName(options.method))},
                                    {"half_width", options.halfWidth},
                                    {"closing", options.closingSteps}};
  return py::cast(std::move(result));
}

std::int64_t eulerCharacteristic(const PyVolume& source, int adjacency, const py::object& progress) {
  if (adjacency != 6 && adjacency != 26)
    throw py::value_error("adjacency: expected 26 or 6, got " + std::to_string(adjacency));
  const volume::Adjacency rule = adjacency == 6 ? volume::Adjacency::Foreground6 : volume::Adjacency::Foreground26;
  if (source.volume.kind() == volume::VolumeKind::Scalar)
    throw InputError("'" + source.volume.name() + "': a scalar field has no solid; use a mask or a distance field");
  CallbackProgress callback(progress);
  std::int64_t chi = 0;
  callback.run([&] {
    const volume::Volume mask =
        source.volume.kind() == volume::VolumeKind::Mask ? source.volume : volume::interiorMask(source.volume);
    chi = volume::eulerCharacteristic(mask, &callback, rule);
  });
  return chi;
}

}  // namespace

pipeline::InputChoices InputKeywords::choices() const {
  pipeline::InputChoices result;
  if (!threshold.is_none()) result.threshold = threshold.cast<double>();
  if (!labels.is_none()) result.labels = labels.cast<std::vector<double>>();
  result.segyBytes = {.inlineByte = inlineByte, .crosslineByte = crosslineByte};
  result.clip = clip;
  if (!mask.is_none()) result.mask = mask.cast<std::string>();
  if (!maskRange.is_none()) result.maskRange = maskRange.cast<std::array<double, 2>>();
  return result;
}

PyVolume loadWithProgress(const std::filesystem::path& path, const pipeline::InputOptions& options,
                          const py::object& progress) {
  CallbackProgress callback(progress);
  pipeline::Statistics stats;
  PyVolume result;
  callback.run([&] { result.volume = pipeline::loadVolume(path, options, &callback, &stats); });
  result.input = stats["input"];
  result.input["read_s"] = stats["timings_s"]["read"];
  return result;
}

void bindVolume(py::module_& m) {
  py::class_<PyVolume>(m, "Volume", R"doc(
A sparse volume: one OpenVDB grid in voxel index space, its kind and its world geometry
(world = origin + spacing * index).

kind is "mask" (binary, inside = active), "scalar" (a sampled field, contoured at an
isovalue) or "distance field" (narrow-band signed distance in voxels, negative inside). Make
one with read_volume(), read_segy(), from_numpy() or distance_field(). A Volume pickles
(process pools, Dask) and copy.deepcopy()s: the grid travels as .vdb bytes, with its
geometry, sampled box and what reading it recorded.)doc")
      .def_property_readonly(
          "kind", [](const PyVolume& v) { return std::string(volume::volumeKindName(v.volume.kind())); },
          "\"mask\", \"scalar\" or \"distance field\".")
      .def_property_readonly(
          "name", [](const PyVolume& v) { return v.volume.name(); },
          "Name of the grid (the source file, or the grid name of a .vdb).")
      .def_property_readonly(
          "spacing", [](const PyVolume& v) { return toTuple(v.volume.geometry().spacing); },
          "World units per voxel along x, y, z.")
      .def_property_readonly(
          "origin", [](const PyVolume& v) { return toTuple(v.volume.geometry().origin); },
          "World position of voxel (0, 0, 0).")
      .def_property_readonly(
          "shape",
          [](const PyVolume& v) {
            const volume::IndexBox box = store::defaultDenseBox(v.volume);
            return py::make_tuple(box.max[0] - box.min[0] + 1, box.max[1] - box.min[1] + 1,
                                  box.max[2] - box.min[2] + 1);
          },
          "Shape of to_numpy() without a box: the sampled box (the input's dims), else the active bounding box.")
      .def("info", &info, R"doc(
Figures of the grid as a dict, as `isovdb info` prints them: kind, active_voxels,
leaf_nodes, active_tiles, grid_memory_bytes, bbox_min/bbox_max (inclusive index box of
the active voxels), spacing, origin, min_value/max_value (fields), sampled_min/sampled_max
(the input's box, when known), and "input": what reading recorded (format, dims, dtype or
sample type, mask rule, SEG-Y geometry, sample percentiles when asked, read time).)doc")
      .def("to_numpy", &toNumpy, py::arg("bbox") = py::none(), R"doc(
Dense copy of a box of the volume, indexed [x, y, z] (C order, z fastest).

bbox: None, or ((x0, y0, z0), (x1, y1, z1)), inclusive index bounds. None: the sampled
box (a volume from from_numpy() returns its array's shape), else the active bounding box.
Returns bool for masks (True inside), float32 otherwise; inactive voxels read as the
grid's background (0 for scalars, the clip value for clipped SEG-Y, +/-half_width
outside the band of a distance field). Raises ValueError for an empty box.)doc")
      .def(py::pickle(&volumeState, &volumeFromState))
      .def("write", &write, py::arg("path"), py::arg("grid_name") = "", R"doc(
Writes the volume by extension: .vdb (one grid with its world transform; distance fields
as level sets in world units, readable by pyopenvdb and VFX tools; grid_name: default
"mask", "field" or "sdf"), or .raw/.nrrd (dense float32 of the sampled box, with an NRRD
header). Written through a temporary file. Raises OSError when the path is not writable.)doc")
      .def("__repr__", [](const PyVolume& v) {
        // A file's name is its quoted label ("'vol.nrrd'", as messages quote it): quoted once here.
        std::string name = v.volume.name();
        if (name.size() >= 2 && name.front() == '\'' && name.back() == '\'') name = name.substr(1, name.size() - 2);
        return "<isovdb.Volume " + std::string(volume::volumeKindName(v.volume.kind())) + " '" + name + "' shape " +
               py::str(py::cast(v).attr("shape")).cast<std::string>() + ">";
      });

  m.def("_from_numpy", &fromNumpyPlaced, py::arg("array"), py::arg("threshold"), py::arg("voxel_size"),
        py::arg("origin"), py::arg("spacing"), py::arg("kind"), py::arg("placement") = py::none(),
        "from_numpy()'s implementation; placement=(first, total): the array holds grid z slices [first, first + "
        "depth) of a volume of total slices (a distributed run's slab).");
  // Defined in Python so that a wrong keyword gets Python's own message naming it (pybind11's
  // lists the overloads and prints the whole array).
  py::exec(R"(def from_numpy(array, threshold=None, voxel_size=1.0, origin=(0.0, 0.0, 0.0), *, spacing=None, kind=None):
    return _from_numpy(array, threshold, voxel_size, origin, spacing, kind)
)",
           m.attr("__dict__"));
  m.attr("from_numpy").attr("__module__") = m.attr("__name__");
  m.attr("from_numpy").attr("__doc__") = R"doc(
Makes a Volume from a 3-D numpy array indexed [x, y, z] (the order of pyopenvdb's
copyFromArray and of the CLI's --dims X,Y,Z; a raw file for the CLI is array.T.tofile()).

array: dtype bool, (u)int8, (u)int16, (u)int32, float32 or float64 (int64/uint64 whose values
  fit in int32, and float16, are converted), every value finite. A C-ordered array or a
  Fortran-ordered one (a [z, y, x] stack's transpose, stack.T: x fastest like a raw file) is
  read in place, without a copy, by the same streaming ingest as a file; other layouts (a
  strided slice) are copied first. Nested lists or tuples are read through numpy.asarray.
threshold: None: integer and bool arrays become a mask (inside = value > 0), float arrays
  a scalar field (contour it with extract(iso=...)). A number: a mask, inside = value > threshold.
kind: None (by dtype and threshold, as above), 'mask' (inside = value > threshold, default 0,
  whatever the dtype) or 'field' (a scalar field whatever the dtype: an integer CT array
  contoured at extract(iso=...) in its own units) or 'distance' (signed distances in world
  units, negative inside as OpenVDB, scikit-fmm and most SDF tools write them: a distance
  field, kept as a band of 3 voxels each side, contoured at 0; voxel_size must be one number).
voxel_size: world units per voxel, one number or (sx, sy, sz); spacing= is the same keyword
  (read_volume's name), give one of them.
origin: world position of voxel [0, 0, 0].

Raises ValueError for anything but an array or nested lists, an array that is not 3-D, empty, of another dtype, or
holding NaN/inf.)doc";

  m.def("read_volume", &readVolume, py::arg("path"), py::kw_only(), py::arg("dims") = py::none(),
        py::arg("dtype") = py::none(), py::arg("big_endian") = false, py::arg("spacing") = py::none(),
        py::arg("header_bytes") = 0, py::arg("threshold") = py::none(), py::arg("labels") = py::none(),
        py::arg("mask") = py::none(), py::arg("mask_range") = py::none(), py::arg("clip") = 0.f,
        py::arg("inline_byte") = 189, py::arg("crossline_byte") = 193, py::arg("scalar") = false, py::arg("grid") = "",
        py::arg("segy") = false, py::arg("sample_statistics") = false, py::arg("progress") = py::none(),
        py::arg("window") = py::none(), R"doc(
Reads a volume file as a sparse Volume: raw (with dims and dtype), NRRD (.nrrd/.nhdr),
MetaImage (.mhd/.mha), NIfTI-1 (.nii/.nii.gz), SEG-Y (.sgy/.segy, or segy=True) or .vdb.
Keywords map one to one
onto the CLI's input flags:

dims=(x, y, z), dtype (numpy dtype or name: "uint8", ">u2", ...), big_endian, spacing
  (number or (sx, sy, sz)), header_bytes: a headerless raw file (--dims --type ...).
threshold: mask, inside = value > threshold (default 0).   labels: mask, inside = value in labels.
mask="above A" | "below A", mask_range=(lo, hi): mask rules (exclude threshold/labels).
scalar: keep the samples as a scalar field (default for SEG-Y without a mask rule).
clip: scalars, samples with |value| < clip stay inactive and the background is clip.
inline_byte, crossline_byte: SEG-Y trace header bytes of the line numbers (189, 193).
grid: .vdb grid name (default: the first float or bool grid).
sample_statistics: also record the samples' range and percentiles in info()["input"].
progress: callable(stage: str, percent: int) called as the reading advances; if it
  raises, the reading stops and its exception propagates.
window=(begin, end): read only the samples whose grid z lies in [begin, end) (one slab of
  a distributed run, isovdb.distributed); the others read as holes (outside a mask). The
  Volume keeps the file's whole index space, geometry and box (a .vdb: only the slab's
  leaves are read; info()["input"] gives the grid's recorded box, file_bbox_min/max).

Raises OSError for a missing or unreadable file, ValueError for a bad header, bad data or
contradicting keywords (the message names the file and the problem).)doc");

  m.def("_euler_characteristic", &eulerCharacteristic, py::arg("volume"), py::arg("adjacency") = 26,
        py::arg("progress") = py::none(), "euler_characteristic()'s implementation, on a Volume.");
  const char* eulerDoc = R"doc(
Euler characteristic of the solid a mask (or a distance field's interior, < 0) describes:
the union of its voxels' closed cubes, components - tunnels + cavities (`isovdb check
--against`). A closed mesh of its boundary should have twice this value:
mesh.check()["euler_characteristic"] == 2 * euler_characteristic(volume).

adjacency: 26 (inside voxels touching at a face, edge or corner are connected) or 6 (faces
only; the reading regular contouring follows, except that each pair of cells regrouped by
Wenger's manifold fix changes the mesh's value by 2).
volume: a Volume, a numpy array (with spacing, origin, kind and threshold as from_numpy()
takes them) or a pyopenvdb grid, as extract() takes it.
Raises ValueError for a scalar field or another adjacency.)doc";

  m.def("_distance_field", &distanceField, py::arg("volume"), py::arg("settings"), py::kw_only(), py::arg("progress"),
        py::arg("output"), py::arg("grid_name"),
        "distance_field()'s implementation: the settings as a dict of keywords.");
  pipeline::DistanceChoices defaults;
  defineSettingsFunction(m, "distance_field", "_distance_field", pipeline::distanceSettings(defaults),
                         {{"progress", "None", "progress: callable(stage, percent); raising cancels and propagates."},
                          {"output", "None",
                           "output: a .vdb path: the band is written there chunk by chunk as `isovdb sdf` does (never\n"
                           "  held whole; a level set in world units) and the statistics are returned as a dict\n"
                           "  instead of a Volume."},
                          {"grid_name", "'sdf'",
                           "grid_name: the grid's name in the output file.\n\n"
                           "Raises ValueError when `volume` is not a mask or a setting is invalid."}},
                         "Narrow-band signed distance field of a mask (kind \"distance field\"): distances in voxels,\n"
                         "NEGATIVE inside, the surface between inside and outside voxel centres, the sign of every\n"
                         "voxel the mask's (the `isovdb sdf` job; voxels beyond the band read +/-half_width).");

  // pyopenvdb grids cross through a .vdb file: pyopenvdb and this module each link their own
  // OpenVDB, so a grid object cannot be shared in memory. extract() and distance_field() take
  // one wherever they take a Volume (_as_volume).
  py::exec(R"py(def from_openvdb(grid):
    import os, tempfile
    try:
        import pyopenvdb
    except ImportError as error:
        raise ValueError("from_openvdb: needs pyopenvdb (Debian: python3-openvdb)") from error
    with tempfile.TemporaryDirectory(prefix="isovdb-") as folder:
        path = os.path.join(folder, "grid.vdb")
        pyopenvdb.write(path, grids=[grid])
        try:
            return read_volume(path, grid=grid.name) if grid.name else read_volume(path)
        except ValueError as error:
            raise ValueError("from_openvdb: " + type(grid).__name__ + " '" + grid.name + "': " +
                             str(error).replace("'" + path + "'", "the grid")) from None


def euler_characteristic(volume, adjacency=26, progress=None, *, spacing=None, origin=None, kind=None,
                         threshold=None):
    volume = _as_volume(volume, "euler_characteristic", spacing=spacing, origin=origin, kind=kind,
                        threshold=threshold)
    return _euler_characteristic(volume, adjacency, progress)


def _as_volume(volume, caller, **array_keywords):
    given = {name: value for name, value in array_keywords.items() if value is not None}
    is_grid = hasattr(volume, "gridClass") and hasattr(volume, "copyToArray")
    if given and (isinstance(volume, Volume) or is_grid):
        raise ValueError(caller + ": " + ", ".join(given) + (" apply" if len(given) > 1 else " applies") +
                         " to a numpy array; a " + ("Volume" if isinstance(volume, Volume) else "grid") +
                         " keeps its own (make it with from_numpy(array, ...) to set them)")
    if isinstance(volume, Volume):
        return volume
    if is_grid:
        return from_openvdb(volume)
    return from_numpy(volume, **given)
)py",
           m.attr("__dict__"));
  m.attr("euler_characteristic").attr("__doc__") = eulerDoc;
  m.attr("from_openvdb").attr("__module__") = m.attr("__name__");
  m.attr("from_openvdb").attr("__doc__") = R"doc(
Makes a Volume from a pyopenvdb grid (Debian's python3-openvdb): a level set (GridClass
LEVEL_SET, world units) becomes a distance field in voxels, a BoolGrid a mask, another
FloatGrid or DoubleGrid a scalar field, with the grid's transform (uniform scale and
translation). The grid crosses through a temporary .vdb file (pyopenvdb links its own
OpenVDB). extract() and distance_field() take a grid directly.

Raises ValueError for a grid type isovdb does not read (vector grids, ...).)doc";
}

}  // namespace isovdb::python
