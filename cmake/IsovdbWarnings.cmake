# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# isovdb_target_warnings(<target>): warnings on for our own code only; errors with
# ISOVDB_WARNINGS_AS_ERRORS (CI sets it: a warning there fails the build).
option(ISOVDB_WARNINGS_AS_ERRORS "Treat warnings in isovdb's own code as errors" OFF)
function(isovdb_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter
    # GCC 12 reports false -Wrestrict positives inside std::string (GCC bug 105329).
    $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>
    $<$<BOOL:${ISOVDB_WARNINGS_AS_ERRORS}>:-Werror>)
endfunction()
