// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/pipeline/extract_to_file.h"

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/mesh_file.h"
#include "isovdb/io/path_util.h"
#include "isovdb/io/ply_stream_writer.h"

namespace isovdb::pipeline {

std::uint64_t extractToFile(volume::Volume volume, const ExtractOptions& options, const std::filesystem::path& path,
                            Interrupter* interrupter, Statistics* stats, const ExtractPart* part) {
  io::checkMeshPath(path);
  io::AtomicFile::checkWritable(path);
  const bool stream = options.contour.method != ContourMethod::Vdb && io::lowerExtension(path) == ".ply";
  if (stream) {
    const volume::Geometry g = volume.geometry();
    io::PlyStreamWriter writer(path, g.spacing, g.origin);
    extractInto(std::move(volume), options, writer, interrupter, stats, part);
    Statistics::StageTimer timer(stats, "write");
    writer.commit();
    if (stats) (*stats)["output"]["streamed"] = true;
    return writer.triangleCount();
  }
  if (part) throw InputError("'" + path.string() + "': a distributed run writes a .ply file");
  const mesh::Mesh mesh = extractMesh(std::move(volume), options, interrupter, stats);
  Statistics::StageTimer timer(stats, "write");
  io::writeMesh(path, mesh);
  return mesh.triangles.size();
}

}  // namespace isovdb::pipeline
