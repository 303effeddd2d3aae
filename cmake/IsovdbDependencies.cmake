# Third-party packages, all from Debian 12 (see README for the apt-get line).
# Debian ships OpenVDB's find module, not a config file.
list(APPEND CMAKE_MODULE_PATH "/usr/lib/x86_64-linux-gnu/cmake/OpenVDB" "/usr/lib/cmake/OpenVDB")
find_package(OpenVDB REQUIRED COMPONENTS openvdb)
find_package(TBB REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(ZLIB REQUIRED)
find_package(CLI11 QUIET CONFIG)
find_package(nlohmann_json 3 REQUIRED)
find_package(CGAL REQUIRED)
