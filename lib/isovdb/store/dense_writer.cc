// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/dense_writer.h"

#include <cstring>
#include <sstream>
#include <vector>

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/store/dense_array.h"
#include "isovdb/io/little_endian.h"
#include "isovdb/io/path_util.h"
#include "isovdb/volume/grids.h"

namespace isovdb::store {

namespace {

std::string nrrdHeader(const volume::Volume& volume, const DenseWriteResult& result, const std::string& dataFile) {
  std::ostringstream out;
  out.precision(17);
  const volume::Geometry& g = volume.geometry();
  out << "NRRD0004\n# isovdb convert: " << volume.name() << " (" << volume::volumeKindName(volume.kind()) << ")\n";
  out << "type: float\ndimension: 3\n";
  out << "sizes: " << result.dims[0] << " " << result.dims[1] << " " << result.dims[2] << "\n";
  out << "endian: little\nencoding: raw\n";
  out << "space dimension: 3\n";
  out << "space directions: (" << g.spacing[0] << ",0,0) (0," << g.spacing[1] << ",0) (0,0," << g.spacing[2] << ")\n";
  out << "space origin: (";
  for (int a = 0; a < 3; ++a) out << (a ? "," : "") << g.origin[a] + g.spacing[a] * result.indexMin[a];
  out << ")\n";
  if (!dataFile.empty()) out << "data file: " << dataFile << "\n";
  out << "\n";
  return out.str();
}

/// Writes the samples of `box`, one z-slice at a time, as little-endian float32.
template <typename GridT, typename ToFloat>
void writeSamples(io::AtomicFile& file, const GridT& grid, const volume::IndexBox& box, ToFloat&& toFloat) {
  typename GridT::ConstAccessor accessor = grid.getConstAccessor();
  const std::size_t nx = static_cast<std::size_t>(box.max[0] - box.min[0] + 1);
  std::vector<char> bytes;
  bytes.reserve(nx * sizeof(float));
  for (int z = box.min[2]; z <= box.max[2]; ++z)
    for (int y = box.min[1]; y <= box.max[1]; ++y) {
      bytes.clear();
      for (std::size_t i = 0; i < nx; ++i)
        io::appendLittleEndian(
            bytes,
            static_cast<float>(toFloat(accessor.getValue(openvdb::Coord(box.min[0] + static_cast<int>(i), y, z)))));
      file.write(bytes.data(), bytes.size());
    }
}

}  // namespace

bool isDenseOutputPath(const std::filesystem::path& path) {
  const std::string ext = io::lowerExtension(path);
  return ext == ".raw" || ext == ".nrrd";
}

DenseWriteResult writeDenseVolume(const std::filesystem::path& path, const volume::Volume& volume) {
  if (!isDenseOutputPath(path))
    throw InputError("'" + path.string() + "': unknown dense format, expected .raw (with a .nhdr header) or .nrrd");
  const volume::IndexBox box = defaultDenseBox(volume);
  DenseWriteResult result;
  for (int a = 0; a < 3; ++a) {
    result.dims[a] = std::int64_t{box.max[a]} - box.min[a] + 1;
    if (result.dims[a] <= 0) throw InputError("'" + volume.name() + "': empty volume, nothing to write");
  }
  result.indexMin = box.min;

  const bool attached = io::lowerExtension(path) == ".nrrd";
  std::filesystem::path headerPath = path;
  if (!attached) headerPath.replace_extension(".nhdr");
  result.header = headerPath;
  io::AtomicFile data(path);
  if (attached) data.write(nrrdHeader(volume, result, ""));
  if (volume.kind() == volume::VolumeKind::Mask)
    writeSamples(data, volume::maskGrid(volume), box, [](bool inside) { return inside ? 1.f : 0.f; });
  else
    writeSamples(data, volume::fieldGrid(volume), box, [](float v) { return v; });
  if (attached) {
    data.commit();
    return result;
  }
  io::AtomicFile header(headerPath);
  header.write(nrrdHeader(volume, result, path.filename().string()));
  data.commit();
  header.commit();
  return result;
}

}  // namespace isovdb::store
