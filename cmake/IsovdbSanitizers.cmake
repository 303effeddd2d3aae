# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# ISOVDB_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer on everything built
# here (CI's sanitizer job, RelWithDebInfo). Any report stops the process
# (-fno-sanitize-recover), so a test that trips one fails.
# ISOVDB_BUILD_FUZZERS: the libFuzzer harnesses of fuzz/ (Clang only; Debian's clang-14
# and libfuzzer-14-dev); they run under the same sanitizers.
option(ISOVDB_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(ISOVDB_BUILD_FUZZERS "Build the libFuzzer harnesses of fuzz/ (Clang)" OFF)
if(ISOVDB_SANITIZE)
  set(isovdb_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_compile_options(${isovdb_sanitizers}
    $<$<CXX_COMPILER_ID:Clang>:-fsanitize-ignorelist=${CMAKE_CURRENT_LIST_DIR}/sanitizer_ignorelist.txt>)
  add_link_options(${isovdb_sanitizers})
endif()
if(ISOVDB_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "ISOVDB_BUILD_FUZZERS needs Clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++-14")
  endif()
  # Coverage feedback from the library, not only from the harnesses; fuzz/ links libFuzzer.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
