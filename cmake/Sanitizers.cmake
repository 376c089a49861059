# Sanitizer and fuzzing builds (included from the top-level CMakeLists.txt
# before any target is defined).
#
#   -DPHONGLAB_SANITIZE=address,undefined
#       every target is compiled and linked with -fsanitize=<list>
#       -fno-omit-frame-pointer, and UBSan does not recover
#       (-fno-sanitize-recover=all): a report ends the process, so a test
#       with undefined behaviour fails. Works with g++ and clang.
#       scripts/test.sh --sanitize uses it (build-sanitize/).
#
#   -DPHONGLAB_FUZZ=ON   (clang only)
#       adds the libFuzzer targets of tests/fuzz (fuzz_<name>); the core, mesh and
#       render libraries, all they link of the project, are compiled with
#       -fsanitize=fuzzer-no-link on top of PHONGLAB_SANITIZE (which defaults
#       to address,undefined here), the fuzz targets are linked with
#       -fsanitize=fuzzer. The same build still makes the ordinary programs
#       and tests (linked without the fuzzer runtime), so one build directory
#       serves both the sanitized test suite and scripts/fuzz.sh.

set(PHONGLAB_SANITIZE "" CACHE STRING
    "Comma-separated -fsanitize= list for every target (e.g. address,undefined); empty: none")
option(PHONGLAB_FUZZ "Build the libFuzzer targets in tests/fuzz (clang only)" OFF)

if(PHONGLAB_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "PHONGLAB_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++-14")
  endif()
  if(PHONGLAB_SANITIZE STREQUAL "")
    set(PHONGLAB_SANITIZE "address,undefined" CACHE STRING
        "Comma-separated -fsanitize= list for every target (e.g. address,undefined); empty: none" FORCE)
  endif()
endif()

if(NOT PHONGLAB_SANITIZE STREQUAL "")
  message(STATUS "PhongLab: sanitizers ${PHONGLAB_SANITIZE}")
  add_compile_options(-fsanitize=${PHONGLAB_SANITIZE} -fno-omit-frame-pointer)
  add_link_options(-fsanitize=${PHONGLAB_SANITIZE})
  if(PHONGLAB_SANITIZE MATCHES "undefined")
    add_compile_options(-fno-sanitize-recover=all)
    add_link_options(-fno-sanitize-recover=all)
  endif()
  # g++ defines __SANITIZE_ADDRESS__ under -fsanitize=address; clang 14 does
  # not (it has __has_feature(address_sanitizer) instead). The project's
  # "#if defined(__SANITIZE_ADDRESS__)" checks (the import child's
  # RLIMIT_AS, which ASan's shadow memory cannot live under) must see it
  # with either compiler. libstdc++ reads either spelling the same way.
  if(PHONGLAB_SANITIZE MATCHES "address" AND CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    add_compile_definitions(__SANITIZE_ADDRESS__=1)
  endif()
endif()

# Called for each library below the GUI: coverage instrumentation for what the
# fuzzers exercise (the other libraries stay uninstrumented, they are not fuzzed).
function(phonglab_instrument_for_fuzzing target)
  if(PHONGLAB_FUZZ)
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
  endif()
endfunction()
