# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# Use ccache when it is installed: OpenVDB headers are heavy and the machine has
# two cores. base_dir makes the cache key independent of where the checkout lives,
# so a fresh clone (as CI makes) reuses what any other checkout compiled.
find_program(ISOVDB_CCACHE ccache)
if(ISOVDB_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER
      ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} CCACHE_NOHASHDIR=true ${ISOVDB_CCACHE})
endif()
