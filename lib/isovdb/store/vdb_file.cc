// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
#include "isovdb/store/vdb_file.h"

#include <openvdb/io/File.h>
#include <openvdb/tools/ChangeBackground.h>
#include <openvdb/tools/ValueTransformer.h>

#include <algorithm>
#include <cmath>

#include "isovdb/errors.h"
#include "isovdb/io/atomic_file.h"
#include "isovdb/io/path_util.h"
#include "isovdb/store/vdb_grid_setup.h"
#include "isovdb/store/vdb_layout.h"
#include "isovdb/volume/grids.h"

namespace isovdb::store {

namespace {

using io::quoted;

using volume::FieldGrid;
using volume::Geometry;
using volume::MaskGrid;
using volume::Volume;
using volume::VolumeKind;

std::string className(openvdb::GridClass gridClass) {
  switch (gridClass) {
    case openvdb::GRID_LEVEL_SET:
      return "level set";
    case openvdb::GRID_FOG_VOLUME:
      return "fog volume";
    case openvdb::GRID_STAGGERED:
      return "staggered";
    default:
      return "unknown";
  }
}

/// Runs OpenVDB's reading in `read`; what it throws (corrupt data deeper than
/// checkVdbLayout looks: KeyError, ValueError, IoError, an oversized allocation)
/// becomes an InputError naming the file.
template <class Read>
auto guardedRead(const std::filesystem::path& path, Read&& read) {
  try {
    return read();
  } catch (const openvdb::Exception& e) {
    throw InputError(quoted(path) + ": not a readable .vdb file (" + std::string(e.what()) + ")");
  } catch (const std::bad_alloc&) {
    throw InputError(quoted(path) + ": not a readable .vdb file (its data asks for more memory than there is)");
  } catch (const std::length_error& e) {
    throw InputError(quoted(path) + ": not a readable .vdb file (" + std::string(e.what()) + ")");
  }
}

std::unique_ptr<openvdb::io::File> openFile(const std::filesystem::path& path) {
  initializeOpenVdb();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw IoError(quoted(path) + ": no such file");
  checkVdbLayout(path);
  auto file = std::make_unique<openvdb::io::File>(path.string());
  file->open(/*delayLoad=*/false);  // callers run inside guardedRead, which names what OpenVDB throws
  return file;
}

/// Index-space geometry of a grid's transform; the grid's own transform is reset.
Geometry takeGeometry(openvdb::GridBase& grid, const std::filesystem::path& path) {
  const openvdb::math::Transform& transform = grid.transform();
  if (!transform.isLinear())
    throw InputError(quoted(path) + ": grid '" + grid.getName() +
                     "' has a non-linear (frustum) transform, expected an axis-aligned scale and translation");
  const openvdb::Mat4d m = transform.baseMap()->getAffineMap()->getMat4();
  Geometry geometry;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c)
      if (r != c && std::abs(m(r, c)) > 1e-12 * std::abs(m(r, r)))
        throw InputError(quoted(path) + ": grid '" + grid.getName() +
                         "' has a rotated or sheared transform, expected an axis-aligned scale and translation");
    geometry.spacing[r] = m(r, r);
    geometry.origin[r] = m(3, r);
    if (!(geometry.spacing[r] > 0))
      throw InputError(quoted(path) + ": grid '" + grid.getName() + "' has a non-positive voxel size");
  }
  grid.setTransform(openvdb::math::Transform::createLinearTransform(1.0));
  return geometry;
}

template <typename GridT>
void scaleLevelSet(GridT& grid, float factor) {
  if (factor == 1.0f) return;  // unit voxels, the usual case: a pass over every value for nothing
  const float background = grid.background() * factor;
  openvdb::tools::foreach (grid.beginValueOn(),
                           [factor](const typename GridT::ValueOnIter& it) { it.setValue(*it * factor); });
  openvdb::tools::changeLevelSetBackground(grid.tree(), background);
}

Volume toVolume(openvdb::GridBase::Ptr base, const std::filesystem::path& path) {
  const std::string name = base->getName();
  if (auto floatGrid = openvdb::gridPtrCast<FieldGrid>(base)) {
    const Geometry geometry = takeGeometry(*floatGrid, path);
    if (floatGrid->getGridClass() == openvdb::GRID_LEVEL_SET) {
      if (!geometry.isUniform())
        throw InputError(quoted(path) + ": level set '" + name + "' has a non-uniform voxel size");
      scaleLevelSet(*floatGrid, static_cast<float>(1.0 / geometry.spacing[0]));
      return Volume(VolumeKind::DistanceField, floatGrid, geometry, path.string());
    }
    return Volume(VolumeKind::Scalar, floatGrid, geometry, path.string());
  }
  if (auto doubleGrid = openvdb::gridPtrCast<openvdb::DoubleGrid>(base)) {
    // Value-converting deep copy: same topology, values rounded to float.
    auto floatGrid = FieldGrid::create(std::make_shared<FieldGrid::TreeType>(doubleGrid->tree()));
    floatGrid->setName(name);
    floatGrid->setGridClass(doubleGrid->getGridClass());
    floatGrid->setTransform(doubleGrid->transform().copy());
    return toVolume(floatGrid, path);
  }
  if (auto boolGrid = openvdb::gridPtrCast<MaskGrid>(base)) {
    const Geometry geometry = takeGeometry(*boolGrid, path);
    return Volume(VolumeKind::Mask, boolGrid, geometry, path.string());
  }
  if (auto maskGrid = openvdb::gridPtrCast<openvdb::MaskGrid>(base)) {
    auto boolGrid =
        MaskGrid::create(std::make_shared<MaskGrid::TreeType>(maskGrid->tree(), false, true, openvdb::TopologyCopy()));
    boolGrid->setName(name);
    boolGrid->setTransform(maskGrid->transform().copy());
    return toVolume(boolGrid, path);
  }
  throw InputError(quoted(path) + ": grid '" + name + "' holds " + base->valueType() +
                   " values, expected a float, double, bool or mask grid");
}

/// The grid's active box as the file records it, if it does.
std::optional<volume::IndexBox> recordedBox(openvdb::io::File& file, const std::string& name) {
  const openvdb::GridBase::ConstPtr meta = file.readGridMetadata(name);
  const auto lo = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MIN);
  const auto hi = meta->getMetadata<openvdb::Vec3IMetadata>(openvdb::GridBase::META_FILE_BBOX_MAX);
  if (!lo || !hi) return std::nullopt;
  return volume::IndexBox{{lo->value().x(), lo->value().y(), lo->value().z()},
                          {hi->value().x(), hi->value().y(), hi->value().z()}};
}

/// The voxels of index z in [z0, z1): read clipped to their world box (a voxel wider; the
/// clipped read keeps whole leaves), then clipped exactly in index space. Across x and y
/// the box is the grid's recorded one (OpenVDB's clipping walks the box's extent); a file
/// that records none is read whole, then clipped.
openvdb::GridBase::Ptr readZWindow(openvdb::io::File& file, const std::string& name,
                                   const std::array<std::int64_t, 2>& window,
                                   const std::optional<volume::IndexBox>& box) {
  constexpr int kFar = 1 << 29;
  const auto z0 = static_cast<int>(std::clamp<std::int64_t>(window[0], -kFar, kFar));
  const auto z1 = static_cast<int>(std::clamp<std::int64_t>(window[1], -kFar, kFar));
  openvdb::GridBase::Ptr grid;
  openvdb::CoordBBox across;
  if (box) {
    across =
        openvdb::CoordBBox(openvdb::Coord(box->min[0], box->min[1], 0), openvdb::Coord(box->max[0], box->max[1], 0));
    const openvdb::GridBase::ConstPtr meta = file.readGridMetadata(name);
    openvdb::BBoxd world;
    for (int corner = 0; corner < 8; ++corner)
      world.expand(meta->transform().indexToWorld(openvdb::Vec3d((corner & 1) ? box->max[0] + 1 : box->min[0] - 1,
                                                                 (corner & 2) ? box->max[1] + 1 : box->min[1] - 1,
                                                                 (corner & 4) ? z1 + 1 : z0 - 1)));
    grid = file.readGrid(name, world);
  } else {
    grid = file.readGrid(name);
    across = grid->evalActiveVoxelBoundingBox();
  }
  grid->clip(openvdb::CoordBBox(openvdb::Coord(across.min().x() - 1, across.min().y() - 1, z0),
                                openvdb::Coord(across.max().x() + 1, across.max().y() + 1, z1 - 1)));
  return grid;
}

/// readVdb's work, inside guardedRead; `window` (optional): only those index z.
Volume readVdbGrid(const std::filesystem::path& path, const std::string& gridName,
                   const std::array<std::int64_t, 2>* window = nullptr,
                   std::optional<volume::IndexBox>* fileBox = nullptr) {
  const auto file = openFile(path);
  std::string name = gridName;
  if (name.empty()) {
    // The first grid of a readable type; its name may be empty (pyopenvdb writes unnamed grids).
    const openvdb::GridPtrVecPtr metadata = file->readAllGridMetadata();
    bool found = false;
    for (const openvdb::GridBase::Ptr& grid : *metadata) {
      const std::string type = grid->valueType();
      if (type == "float" || type == "double" || type == "bool" || type == "mask") {
        name = grid->getName();
        found = true;
        break;
      }
    }
    if (!found) throw InputError(quoted(path) + ": no float, double, bool or mask grid in the file");
  } else if (!file->hasGrid(name)) {
    std::string names;
    for (auto it = file->beginName(); it != file->endName(); ++it) names += (names.empty() ? "" : ", ") + *it;
    throw InputError(quoted(path) + ": no grid named '" + name + "' (the file has: " + names + ")");
  }
  openvdb::GridBase::Ptr grid;
  try {
    if (window) {
      const std::optional<volume::IndexBox> box = recordedBox(*file, name);
      if (fileBox) *fileBox = box;
      grid = readZWindow(*file, name, *window, box);
    } else {
      grid = file->readGrid(name);
    }
  } catch (const openvdb::Exception& e) {
    throw InputError(quoted(path) + ": cannot read grid '" + name + "' (" + std::string(e.what()) + ")");
  }
  file->close();
  return toVolume(grid, path);
}

}  // namespace

std::vector<VdbGridInfo> listVdbGrids(const std::filesystem::path& path) {
  return guardedRead(path, [&] {
    const auto file = openFile(path);
    std::vector<VdbGridInfo> grids;
    const openvdb::GridPtrVecPtr metadata = file->readAllGridMetadata();
    for (const openvdb::GridBase::Ptr& grid : *metadata)
      grids.push_back({grid->getName(), grid->valueType(), className(grid->getGridClass())});
    file->close();
    return grids;
  });
}

Volume readVdb(const std::filesystem::path& path, const std::string& gridName) {
  return guardedRead(path, [&] { return readVdbGrid(path, gridName); });
}

Volume readVdb(const std::filesystem::path& path, const std::string& gridName,
               const std::array<std::int64_t, 2>& zWindow, std::optional<volume::IndexBox>* fileBox) {
  return guardedRead(path, [&] { return readVdbGrid(path, gridName, &zWindow, fileBox); });
}

void writeVdb(const std::filesystem::path& path, const Volume& volume, const VdbWriteOptions& options) {
  initializeOpenVdb();
  if (!volume.valid()) throw InputError("writeVdb: empty volume for " + quoted(path));
  const Geometry& geometry = volume.geometry();
  openvdb::GridBase::Ptr out;
  std::string defaultName;
  const bool levelSet = volume.kind() == VolumeKind::DistanceField;
  if (volume.kind() == VolumeKind::Mask) {
    out = volume.grid()->copyGrid();  // shares the tree: only the transform and name differ
    defaultName = "mask";
  } else {
    const FieldGrid::Ptr grid = volume::fieldGridPtr(volume);
    const float scale = levelSetWorldScale(geometry);
    if (levelSet && scale != 1.f) {
      FieldGrid::Ptr scaled = grid->deepCopy();
      scaleLevelSet(*scaled, scale);
      out = scaled;
    } else {
      out = grid->copyGrid();
    }
    defaultName = levelSet ? "sdf" : "field";
  }
  describeGrid(*out, geometry, options.gridName.empty() ? defaultName : options.gridName, levelSet, volume.name());

  io::AtomicFile target(path);
  target.closeStream();
  try {
    openvdb::io::File file(target.temporaryPath().string());
    file.write(openvdb::GridCPtrVec{out});
    file.close();
  } catch (const openvdb::Exception& e) {
    throw IoError("cannot write " + quoted(path) + ": " + std::string(e.what()));
  }
  target.commit();
}

}  // namespace isovdb::store
