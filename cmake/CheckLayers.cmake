# Checks that app/'s layers point one way: every #include "LAYER/..." in a
# file of app/<layer>/ names a layer that layer may use.
#
#   cmake -P cmake/CheckLayers.cmake          (from the source tree's root)
#
# Prints each upward edge as FILE:LINE: includes LAYER/... and fails when
# there is one. Registered with CTest as unit.layers. The libraries enforce
# the same order at link time (app/CMakeLists.txt): a layer links only the
# ones listed here for it.
cmake_minimum_required(VERSION 3.16)
get_filename_component(root "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)

set(allowed_core   core)
set(allowed_mesh   core mesh)
set(allowed_render core mesh render)
set(allowed_bench  core mesh render bench)
set(allowed_ui     core mesh render bench ui)
set(allowed_cli    core mesh render bench cli)
set(layers core mesh render bench ui cli)

set(violations 0)
foreach(layer IN LISTS layers)
  file(GLOB files "${root}/app/${layer}/*.h" "${root}/app/${layer}/*.cpp")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" lines)
    set(number 0)
    foreach(line IN LISTS lines)
      math(EXPR number "${number} + 1")
      if(line MATCHES "^#include \"([a-z]+)/")
        set(target "${CMAKE_MATCH_1}")
        list(FIND layers "${target}" known)
        list(FIND allowed_${layer} "${target}" ok)
        if(known GREATER -1 AND ok EQUAL -1)
          file(RELATIVE_PATH relative "${root}" "${file}")
          message("${relative}:${number}: includes ${target}/..., above the ${layer} layer")
          math(EXPR violations "${violations} + 1")
        endif()
      endif()
    endforeach()
  endforeach()
endforeach()

if(violations GREATER 0)
  message(FATAL_ERROR "${violations} include(s) point up the layers (core <- mesh <- render <- bench, ui, cli)")
endif()
message(STATUS "layers: every include points down (core <- mesh <- render <- bench <- ui; bench <- cli)")
