# Checks that app/'s layers point one way: every #include "LAYER/..." in a
# file of app/<layer>/ names a layer that layer may use.
#
#   cmake -P cmake/CheckLayers.cmake          (from the source tree's root)
#
# Prints each upward edge as FILE:LINE: includes LAYER/... and fails when
# there is one. core and mesh use Qt Core alone: any <Q...> header they
# include must be one of QtCore's (pass -DQT_CORE_INCLUDE_DIR=... where Qt
# is not under /usr/include/<triplet>/qt6). Below charts no file includes a
# header of Qt Widgets, Qt Charts or Qt OpenGL Widgets. Registered with CTest as unit.layers. The libraries enforce
# the same order at link time (app/CMakeLists.txt): a layer links only the
# ones listed here for it.
#
# Inside core and mesh the rooms (docs/architecture.md) have rules of their
# own: support/ is the floor and includes no other room; program/ (the
# vocabulary of a shader program: stages, dialect, bindings, the course's
# prelude, tokens, lint) stands on support/ alone; check/ judges
# images and programs and does not read scene files (scene/SceneJson*,
# ScenePaths, RecoveryJournal): a check gets its scene already read, which
# is what lets the window, the CLI and the grader hand it the same Scene.
cmake_minimum_required(VERSION 3.16)
get_filename_component(root "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)

set(allowed_headless headless)
set(allowed_core   core)
set(allowed_mesh   core mesh)
set(allowed_render headless core mesh render)
set(allowed_bench  core mesh render bench)
set(allowed_charts core mesh render bench charts)
set(allowed_ui     core mesh render bench charts ui)
set(allowed_cli    headless core mesh render bench cli)
set(allowed_benchcli core mesh render bench charts cli benchcli)
set(layers headless core mesh render bench charts ui cli benchcli)

if(NOT QT_CORE_INCLUDE_DIR)
  file(GLOB QT_CORE_INCLUDE_DIR /usr/include/*/qt6/QtCore /usr/include/qt6/QtCore)
  list(GET QT_CORE_INCLUDE_DIR 0 QT_CORE_INCLUDE_DIR)
endif()
set(qt_core_only core mesh)
# Only charts, ui and benchcli may draw with widgets (Qt Widgets, Qt Charts).
get_filename_component(qt_include_root "${QT_CORE_INCLUDE_DIR}" DIRECTORY)
set(widget_modules QtWidgets QtCharts QtOpenGLWidgets)
set(no_widgets headless core mesh render bench cli)
if(NOT EXISTS "${qt_include_root}/QtWidgets")
  message(FATAL_ERROR "Qt Widgets' headers are not at ${qt_include_root}/QtWidgets: "
                      "cannot tell a widget header (pass -DQT_CORE_INCLUDE_DIR=...)")
endif()

# ROOM "INCLUDE REGEX" "WHY": an include of a file of app/ROOM/ matching
# the regex is refused.
set(room_rules
  "core/support" "^(core/(scene|view|reference|check|project|program)|mesh)/" "support/ is the floor of core"
  "core/program" "^(core/(scene|view|reference|check|project)|mesh)/" "program/ is the vocabulary of a shader program, below scene and check"
  "core/check" "^core/scene/(SceneJson[A-Za-z]*|ScenePaths|RecoveryJournal)\\.h$" "check/ does not read scene files"
  "mesh/detail" "^mesh/import/(MeshLoader|MeshImportProcess|MeshCache|SceneMeshes)\\.h$" "detail/ works on meshes already loaded")
# page/ runs a student's page and reads its capture: it stands on the rest
# of core, and no other room of core includes it.
foreach(room support program scene view reference check project)
  list(APPEND room_rules "core/${room}" "^core/page/" "page/ stands above the other rooms of core")
endforeach()
set(known_rooms
  core/scene core/reference core/check core/view core/support core/project core/program core/page
  mesh/import mesh/normals mesh/detail)

set(violations 0)
foreach(layer core mesh)
  file(GLOB entries LIST_DIRECTORIES true "${root}/app/${layer}/*")
  foreach(entry IN LISTS entries)
    get_filename_component(name "${entry}" NAME)
    if(IS_DIRECTORY "${entry}" AND NOT "${layer}/${name}" IN_LIST known_rooms)
      message("app/${layer}/${name}/: a room CheckLayers.cmake does not know (add it to known_rooms and to docs/architecture.md)")
      math(EXPR violations "${violations} + 1")
    elseif(NOT IS_DIRECTORY "${entry}")
      message("app/${layer}/${name}: outside the rooms of ${layer} (docs/architecture.md)")
      math(EXPR violations "${violations} + 1")
    endif()
  endforeach()
endforeach()
list(LENGTH room_rules rule_fields)
math(EXPR last_rule "${rule_fields} - 1")
foreach(at RANGE 0 ${last_rule} 3)
  math(EXPR at_regex "${at} + 1")
  math(EXPR at_why "${at} + 2")
  list(GET room_rules ${at} room)
  list(GET room_rules ${at_regex} refused)
  list(GET room_rules ${at_why} why)
  file(GLOB_RECURSE files "${root}/app/${room}/*.h" "${root}/app/${room}/*.cpp")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" lines REGEX "^#include \"")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
      if(included MATCHES "${refused}")
        file(RELATIVE_PATH relative "${root}" "${file}")
        message("${relative}: includes ${included}: ${why}")
        math(EXPR violations "${violations} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()
foreach(layer IN LISTS layers)
  file(GLOB_RECURSE files "${root}/app/${layer}/*.h" "${root}/app/${layer}/*.cpp")
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
      if(layer IN_LIST qt_core_only AND line MATCHES "^#include <(Q[A-Za-z/]+)>")
        set(included "${CMAKE_MATCH_1}")
        string(REGEX REPLACE "^QtCore/" "" header "${included}")
        if(NOT EXISTS "${QT_CORE_INCLUDE_DIR}/${header}")
          file(RELATIVE_PATH relative "${root}" "${file}")
          message("${relative}:${number}: includes <${included}>, not Qt Core: the ${layer} layer has no Qt GUI")
          math(EXPR violations "${violations} + 1")
        endif()
      endif()
      # <QWidget>, <QtWidgets/QWidget> and the lower-case <qwidget.h> alike.
      if(layer IN_LIST no_widgets AND line MATCHES "^#include [<\"]((Q[A-Za-z/]+)|(q[a-z0-9_]+\\.h))[>\"]")
        set(included "${CMAKE_MATCH_1}")
        foreach(module IN LISTS widget_modules)
          string(REGEX REPLACE "^${module}/" "" header "${included}")
          if(EXISTS "${qt_include_root}/${module}/${header}")
            file(RELATIVE_PATH relative "${root}" "${file}")
            message("${relative}:${number}: includes <${included}> (${module}): the ${layer} layer draws no widgets")
            math(EXPR violations "${violations} + 1")
          endif()
        endforeach()
      endif()
    endforeach()
  endforeach()
endforeach()

if(violations GREATER 0)
  message(FATAL_ERROR "${violations} include(s) point up the layers (core <- mesh <- render <- bench <- charts <- ui; headless <- render; headless, bench <- cli <- benchcli; charts <- benchcli), reach past Qt Core, draw widgets below charts, or break a room's rule")
endif()
message(STATUS "layers: every include points down and every room keeps its rules (core <- mesh <- render <- bench <- charts <- ui; headless <- render; headless, bench <- cli <- benchcli; charts <- benchcli); core and mesh use Qt Core alone; only charts, ui and benchcli use widgets")
