// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/io/mesh_file.h"

#include <string>

#include "isovdb/errors.h"
#include "isovdb/io/glb.h"
#include "isovdb/io/gltf_reader.h"
#include "isovdb/io/obj.h"
#include "isovdb/io/path_util.h"
#include "isovdb/io/ply.h"
#include "isovdb/io/stl.h"

namespace isovdb::io {

namespace {
std::string unknownFormat(const std::filesystem::path& path, const std::string& ext) {
  return "'" + path.string() + "': unknown mesh format '" + ext + "', expected .ply, .obj, .stl or .glb";
}
}  // namespace

void checkMeshPath(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".ply" && ext != ".obj" && ext != ".stl" && ext != ".glb") throw InputError(unknownFormat(path, ext));
}

void writeMesh(const std::filesystem::path& path, const mesh::Mesh& mesh) {
  const std::string ext = lowerExtension(path);
  if (ext == ".ply") return writePly(path, mesh);
  if (ext == ".obj") return writeObj(path, mesh);
  if (ext == ".stl") return writeStl(path, mesh);
  if (ext == ".glb") return writeGlb(path, mesh);
  throw InputError(unknownFormat(path, ext));
}

mesh::Mesh readMesh(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".ply") return readPly(path);
  if (ext == ".obj") return readObj(path);
  if (ext == ".stl") return readStl(path);
  if (ext == ".glb" || ext == ".gltf") return readGltf(path);
  throw InputError("'" + path.string() + "': unknown mesh format '" + ext +
                   "', expected .ply, .obj, .stl, .glb or .gltf");
}

}  // namespace isovdb::io
