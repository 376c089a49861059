# How the tree builds in minutes on a 2-core machine (issue 32; figures:
# scripts/build-time.sh). Included from the top-level CMakeLists.txt after
# Sanitizers, before any target.
#
#   Debug info where somebody reads it. Plain builds give the libraries and
#   the program line tables (-g1: backtraces name functions and lines) and
#   the test and benchmark programs none: -g doubled the compile time of a
#   UI test and made its object 20 times larger, for a debugger nobody
#   attaches there. PHONGLAB_DEBUG_INFO=full restores -g everywhere.
#   Sanitizer builds keep their own flags (scripts/build.sh --sanitize).
#
#   Precompiled headers (PHONGLAB_PCH, on): each library precompiles the Qt,
#   GLM and standard headers of its layer (Qt's headers make `emit`,
#   `signals` and `slots` macros: no identifier may be one of those words
#   anywhere now); the tests share one per set of
#   Qt modules their libraries bring (a header precompiled with
#   QT_WIDGETS_LIB defined is refused where it is not, and QTEST_MAIN
#   differs with it). OpenMesh's
#   headers are left out: no more than two files of mesh include any one of
#   them. ccache caches such files only with its PCH sloppiness, which
#   scripts/build.sh sets in the compiler launcher.

set(PHONGLAB_DEBUG_INFO "lines" CACHE STRING
    "Debug info in plain builds: lines (-g1 in libraries, none in tests), full (-g everywhere)")
option(PHONGLAB_PCH "Precompiled headers for Qt, GLM and the standard library" ON)

set(phonglab_plain_build FALSE)
if(PHONGLAB_SANITIZE STREQUAL "" AND PHONGLAB_DEBUG_INFO STREQUAL "lines"
   AND CMAKE_BUILD_TYPE STREQUAL "RelWithDebInfo")
  set(phonglab_plain_build TRUE)
  set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O2 -g1") # asserts live: they guard invariants
endif()

set(PHONGLAB_PCH_CORE
    <QByteArray> <QDir> <QFileInfo> <QJsonObject> <QList> <QString> <QStringList>
    <glm/glm.hpp> <algorithm> <array> <cmath> <cstdint> <functional> <limits> <map> <memory>
    <optional> <span> <utility> <vector>)
set(PHONGLAB_PCH_RENDER ${PHONGLAB_PCH_CORE}
    <QImage> <QObject> <QOpenGLContext> <QOpenGLExtraFunctions> <QOpenGLFunctions> <QSize>)
set(PHONGLAB_PCH_UI ${PHONGLAB_PCH_RENDER}
    <QAction> <QCheckBox> <QComboBox> <QDockWidget> <QHBoxLayout> <QLabel> <QMainWindow>
    <QMenu> <QPushButton> <QVBoxLayout> <QWidget>)

# A library's precompiled headers, by its kind (core, render or ui:
# PHONGLAB_PCH_<layer> in cmake/Layers.cmake).
function(phonglab_precompile target layer)
  if(NOT PHONGLAB_PCH)
    return()
  endif()
  string(TOUPPER ${layer} upper)
  target_precompile_headers(${target} PRIVATE ${PHONGLAB_PCH_${upper}})
endfunction()

# A test program: the precompiled headers of the first test whose libraries
# give it the same Qt modules (so the same QT_*_LIB definitions, which a
# precompiled header must match), made once and reused by the rest: five
# sets at most (core, render, bench, charts, ui) rather than one per set of
# libraries, which made ~30 headers of ~10 s each.
function(phonglab_test_program target kind libs)
  if(NOT PHONGLAB_PCH)
    return()
  endif()
  # The highest group among the layers of its libraries (cmake/Layers.cmake);
  # the test supports count as the layers they link.
  set(modules core)
  set(rank 0)
  foreach(lib IN LISTS libs)
    string(REGEX REPLACE "^phonglab_" "" layer "${lib}")
    string(REPLACE "test_support_gl" "render" layer "${layer}")
    string(REPLACE "test_support_ui" "ui" layer "${layer}")
    if(DEFINED PHONGLAB_TEST_GROUP_${layer})
      list(FIND PHONGLAB_TEST_GROUPS ${PHONGLAB_TEST_GROUP_${layer}} at)
      if(at GREATER rank)
        set(rank ${at})
        set(modules ${PHONGLAB_TEST_GROUP_${layer}})
      endif()
    endif()
  endforeach()
  set(pch_of_group_core CORE)
  set(pch_of_group_render RENDER)
  set(pch_of_group_bench RENDER)
  set(pch_of_group_charts UI)
  set(pch_of_group_ui UI)
  set(headers ${PHONGLAB_PCH_${pch_of_group_${modules}}})
  get_property(anchor GLOBAL PROPERTY PHONGLAB_PCH_ANCHOR_${modules})
  if(anchor)
    target_precompile_headers(${target} REUSE_FROM ${anchor})
    return()
  endif()
  set_property(GLOBAL PROPERTY PHONGLAB_PCH_ANCHOR_${modules} ${target})
  target_precompile_headers(${target} PRIVATE ${headers} <QTest>)
endfunction()
