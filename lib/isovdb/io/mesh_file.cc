#include "isovdb/io/mesh_file.h"

#include <algorithm>
#include <string>

#include "isovdb/errors.h"
#include "isovdb/io/obj.h"
#include "isovdb/io/ply.h"

namespace isovdb::io {

namespace {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace

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
