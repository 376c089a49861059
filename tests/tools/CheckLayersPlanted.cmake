# unit.layersplanted: cmake/CheckLayers.cmake catches each kind of breach.
# Copies app/ (its .h and .cpp) to WORK, checks the copy passes, then
# plants one breach at a time and expects CheckLayers to fail naming the
# planted file and the reason.
#
#   cmake -DROOT=<source tree> -DWORK=<scratch folder> -P CheckLayersPlanted.cmake
cmake_minimum_required(VERSION 3.19)
set(checker "${ROOT}/cmake/CheckLayers.cmake")

function(run_checker out_rc out_text)
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${WORK} -P ${checker}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_text} "${out}${err}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${WORK}")
file(COPY "${ROOT}/app" DESTINATION "${WORK}" FILES_MATCHING PATTERN "*.h" PATTERN "*.cpp")
run_checker(rc text)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the unplanted copy already fails:\n${text}")
endif()

# FILE (in app/) | LINE TO ADD | what the message must say
set(plants
  "core/scene/Scene.h" "#include \"core/check/ShaderCheck.h\""
    "core/check/ stands above core/scene/"
  "mesh/import/PolygonMesh.h" "#include \"mesh/loading/MeshLoader.h\""
    "mesh/loading/ stands above mesh/import/"
  "core/support/Result.h" "#include \"render/draw/Renderer.h\""
    "the render layer is not below core"
  "render/gl/GpuMesh.h" "#include <QWidget>"
    "the render layer draws no widgets"
  "core/view/Camera.h" "#include <QImage>"
    "not Qt Core"
  "ui/viewport/Viewport.h" "#include \"ui/window/MainWindow.h\""
    "ui/window/ stands above ui/viewport/"
  "cli/common/CliCommon.h" "#include \"grade/GradeRows.h\""
    "neither a file of this folder nor a path from app/"
  "core/check/ShaderCheck.h" "#include \"core/scene/ScenePaths.h\""
    "check/ does not read scene files")

list(LENGTH plants fields)
math(EXPR last "${fields} - 1")
set(missed 0)
foreach(at RANGE 0 ${last} 3)
  math(EXPR at_line "${at} + 1")
  math(EXPR at_says "${at} + 2")
  list(GET plants ${at} file)
  list(GET plants ${at_line} line)
  list(GET plants ${at_says} says)
  set(path "${WORK}/app/${file}")
  file(READ "${path}" original)
  file(APPEND "${path}" "\n${line}\n")
  run_checker(rc text)
  file(WRITE "${path}" "${original}")
  if(rc EQUAL 0 OR NOT text MATCHES "app/${file}:[0-9]+: [^\n]*${says}")
    message("not caught: ${line} in app/${file} (expected \"${says}\"):\n${text}")
    math(EXPR missed "${missed} + 1")
  endif()
endforeach()

# A file outside the rooms of a layer that has them.
file(WRITE "${WORK}/app/render/Stray.h" "#pragma once\n")
run_checker(rc text)
file(REMOVE "${WORK}/app/render/Stray.h")
if(rc EQUAL 0 OR NOT text MATCHES "app/render/Stray.h: outside the rooms of render")
  message("not caught: app/render/Stray.h outside render's rooms:\n${text}")
  math(EXPR missed "${missed} + 1")
endif()

if(missed GREATER 0)
  message(FATAL_ERROR "${missed} planted breach(es) not caught")
endif()
message(STATUS "layers: every planted breach caught")
