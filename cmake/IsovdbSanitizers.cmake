# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# ISOVDB_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer on everything built
# here (CI's sanitizer job, RelWithDebInfo). Any report stops the process
# (-fno-sanitize-recover; alignment recovers only so that ubsan_suppressions.txt can name
# TBB's, and halt_on_error=1 stops on the rest), so a test that trips one fails. The
# suppressions reach the tests through ISOVDB_SANITIZER_ENVIRONMENT (UBSAN_OPTIONS) rather
# than a compile-time ignorelist: an absolute path in the compile flags differs per clone,
# and ccache (base_dir rewrites only include paths) then missed every file in CI.
# ISOVDB_BUILD_FUZZERS: the libFuzzer harnesses of fuzz/ (Clang only; Debian's clang-14
# and libfuzzer-14-dev); they run under the same sanitizers.
option(ISOVDB_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(ISOVDB_BUILD_FUZZERS "Build the libFuzzer harnesses of fuzz/ (Clang)" OFF)
if(ISOVDB_SANITIZE)
  set(isovdb_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=all
    -fsanitize-recover=alignment -fno-omit-frame-pointer)
  add_compile_options(${isovdb_sanitizers})
  add_link_options(${isovdb_sanitizers})
  set(ISOVDB_SANITIZER_ENVIRONMENT
    "UBSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/ubsan_suppressions.txt:halt_on_error=1:print_stacktrace=1")
endif()

# isovdb_sanitize_directory_tests(): every test added so far in this folder runs with the
# sanitizer environment (nothing without ISOVDB_SANITIZE).
function(isovdb_sanitize_directory_tests)
  get_property(tests DIRECTORY PROPERTY TESTS)
  if(ISOVDB_SANITIZE AND tests)
    set_property(TEST ${tests} APPEND PROPERTY ENVIRONMENT "${ISOVDB_SANITIZER_ENVIRONMENT}")
  endif()
endfunction()
if(ISOVDB_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "ISOVDB_BUILD_FUZZERS needs Clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++-14")
  endif()
  # Coverage feedback from the library, not only from the harnesses; fuzz/ links libFuzzer.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
