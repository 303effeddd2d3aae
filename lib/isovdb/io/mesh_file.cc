// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/mesh_file.h"

#include <string>

#include "isovdb/errors.h"
#include "isovdb/io/obj.h"
#include "isovdb/io/path_util.h"
#include "isovdb/io/ply.h"

namespace isovdb::io {

bool isMeshPath(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".ply" || ext == ".obj";
}

void writeMesh(const std::filesystem::path& path, const mesh::Mesh& mesh) {
  const std::string ext = lowerExtension(path);
  if (ext == ".ply") return writePly(path, mesh);
  if (ext == ".obj") return writeObj(path, mesh);
  throw InputError("'" + path.string() + "': unknown mesh format '" + ext + "', expected .ply or .obj");
}

mesh::Mesh readMesh(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".ply") throw InputError("'" + path.string() + "': can only read .ply meshes");
  return readPly(path);
}

}  // namespace isovdb::io
