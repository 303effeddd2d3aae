// SPDX-License-Identifier: MPL-2.0
// Copyright Contributors to the isovdb project.
/// @file gltf_codes.h
/// @brief The numbers of the glTF 2.0 format that its writer (glb.cc) and reader
///        (gltf_reader.cc) share.
#pragma once

#include <cstdint>

namespace isovdb::io::gltf {

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr int kFloat = 5126;                      // accessor componentType codes
constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kTriangles = 4;  // primitive mode

}  // namespace isovdb::io::gltf
