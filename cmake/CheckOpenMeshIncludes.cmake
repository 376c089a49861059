# Checks that app/ and tests/ include OpenMesh only through
# app/mesh/import/OpenMeshHeaders.h, which turns OpenMesh's own asserts off
# around its headers (it says why). An inline OpenMesh function compiled in
# one file with its asserts and in another without is two definitions of one
# function, and the linker keeps either, so one direct include would bring
# the slow checks back. OpenMesh/Core/System/config.h, the version macros
# alone, may be included directly.
#
#   cmake -P cmake/CheckOpenMeshIncludes.cmake     (the source tree)
#   cmake -DROOT=DIR -P cmake/CheckOpenMeshIncludes.cmake
#
# Prints each breach as FILE:LINE: #include <OpenMesh/...> and fails when
# there is one. Registered with CTest as unit.openmeshincludes;
# unit.openmeshincludesplanted plants one in a scratch tree.
cmake_minimum_required(VERSION 3.19)
if(NOT ROOT)
  set(ROOT "${CMAKE_CURRENT_LIST_DIR}/..")
endif()
get_filename_component(root "${ROOT}" ABSOLUTE)
set(wrapper "app/mesh/import/OpenMeshHeaders.h")

file(GLOB_RECURSE sources RELATIVE "${root}"
     "${root}/app/*.h" "${root}/app/*.cpp" "${root}/tests/*.h" "${root}/tests/*.cpp")
list(SORT sources)
set(breaches "")
foreach(relative IN LISTS sources)
  if(relative STREQUAL wrapper)
    continue()
  endif()
  # The "\n" in front makes an include on the first line findable; `rest`
  # begins at line `line` (0: that "\n").
  file(READ "${root}/${relative}" text)
  set(rest "\n${text}")
  set(line 0)
  while(TRUE)
    string(REGEX MATCH "\n[ \t]*#[ \t]*include[ \t]*[<\"]OpenMesh/[^\n]*" found "${rest}")
    if(NOT found)
      break()
    endif()
    string(FIND "${rest}" "${found}" at)
    string(SUBSTRING "${rest}" 0 ${at} before)
    string(REGEX REPLACE "[^\n]" "" newlines "${before}")
    string(LENGTH "${newlines}" skipped)
    math(EXPR line "${line} + ${skipped} + 1")
    string(STRIP "${found}" directive)
    if(NOT directive MATCHES "OpenMesh/Core/System/config\\.h")
      list(APPEND breaches "${relative}:${line}: ${directive}")
    endif()
    string(LENGTH "${found}" length)
    math(EXPR next "${at} + ${length}")
    string(SUBSTRING "${rest}" ${next} -1 rest)
  endwhile()
endforeach()

list(LENGTH breaches count)
if(count GREATER 0)
  foreach(breach IN LISTS breaches)
    message("${breach}") # one line each, unwrapped: FILE:LINE for an editor
  endforeach()
  message(FATAL_ERROR "${count} include(s) of OpenMesh not through ${wrapper} (it says why)")
endif()
message(STATUS "OpenMesh is included through ${wrapper} alone")
