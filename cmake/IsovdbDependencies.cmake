# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# Third-party packages, all from Debian 12 (see README for the apt-get line).
# Debian ships OpenVDB's find module, not a config file.
list(APPEND CMAKE_MODULE_PATH "/usr/lib/x86_64-linux-gnu/cmake/OpenVDB" "/usr/lib/cmake/OpenVDB")
find_package(OpenVDB REQUIRED COMPONENTS openvdb)
find_package(TBB REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(ZLIB REQUIRED)
find_package(BZip2 REQUIRED)
find_package(CLI11 QUIET CONFIG)
find_package(nlohmann_json 3 REQUIRED)
find_package(CGAL REQUIRED)
# SEG-Y reading: segyio's C library (Debian libsegyio-dev). Its packaged CMake
# config lacks the per-configuration file, so the target is made here.
find_path(SEGYIO_INCLUDE_DIR segyio/segy.h REQUIRED)
find_library(SEGYIO_LIBRARY segyio REQUIRED)
if(NOT TARGET isovdb_segyio)
  add_library(isovdb_segyio UNKNOWN IMPORTED)
  set_target_properties(isovdb_segyio PROPERTIES IMPORTED_LOCATION "${SEGYIO_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${SEGYIO_INCLUDE_DIR}" INTERFACE_LINK_LIBRARIES m)
endif()
# Slice images (morph): stb_image reads PNG and BMP (1-bit monochrome included),
# stb_image_write writes the intermediate slices as PNG (Debian libstb-dev).
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
