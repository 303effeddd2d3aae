// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file extract_to_file.h
/// @brief The main job straight into a mesh file, as `isovdb extract -o` runs it (the CLI
///        and the Python bindings share it, so both write the same bytes).
#pragma once

#include <cstdint>
#include <filesystem>

#include "isovdb/pipeline/extract.h"

namespace isovdb::pipeline {

/// Contours `volume` into `path` (.ply, .obj or .stl, by extension). The octree methods
/// stream a .ply meta-cell by meta-cell (the mesh is never held whole; the header
/// keeps room for the final counts); otherwise the mesh is built and written whole.
/// Written through a temporary file. Records "output.streamed" and a "write" timing.
/// `volume` by value, as extractMesh takes it (move a mask in to have it freed early).
/// @return the number of triangles written
/// @throw InputError for another extension or invalid options; IoError when the path
///        is not writable (checked before the work starts); Interrupted on cancellation.
/// `part`: the client of a distributed run (ExtractPart::received).
std::uint64_t extractToFile(volume::Volume volume, const ExtractOptions& options, const std::filesystem::path& path,
                            Interrupter* interrupter = nullptr, Statistics* stats = nullptr,
                            const ExtractPart* part = nullptr);

}  // namespace isovdb::pipeline
