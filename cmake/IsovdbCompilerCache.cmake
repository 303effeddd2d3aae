# Use ccache when it is installed: OpenVDB headers are heavy and the machine has two cores.
find_program(ISOVDB_CCACHE ccache)
if(ISOVDB_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER "${ISOVDB_CCACHE}")
endif()
