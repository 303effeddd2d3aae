# isovdb_target_warnings(<target>): warnings on for our own code only.
function(isovdb_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wno-unused-parameter)
endfunction()
