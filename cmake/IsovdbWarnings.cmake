# isovdb_target_warnings(<target>): warnings on for our own code only.
function(isovdb_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter
    # GCC 12 reports false -Wrestrict positives inside std::string (GCC bug 105329).
    $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
endfunction()
