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
  set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O2 -g1 -DNDEBUG")
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

# A library's precompiled headers, by its layer (core, render or ui).
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
  set(modules core)
  set(headers ${PHONGLAB_PCH_CORE})
  if(libs MATCHES "phonglab_(render|bench|cli|charts|benchcli|ui|test_support_gl|test_support_ui)")
    set(modules render)
    set(headers ${PHONGLAB_PCH_RENDER})
  endif()
  if(libs MATCHES "phonglab_(bench|cli|charts|benchcli|ui|test_support_ui)")
    set(modules bench)
  endif()
  if(libs MATCHES "phonglab_(charts|benchcli|ui|test_support_ui)")
    set(modules charts)
    set(headers ${PHONGLAB_PCH_UI})
  endif()
  if(libs MATCHES "phonglab_(ui|test_support_ui)")
    set(modules ui)
  endif()
  get_property(anchor GLOBAL PROPERTY PHONGLAB_PCH_ANCHOR_${modules})
  if(anchor)
    target_precompile_headers(${target} REUSE_FROM ${anchor})
    return()
  endif()
  set_property(GLOBAL PROPERTY PHONGLAB_PCH_ANCHOR_${modules} ${target})
  target_precompile_headers(${target} PRIVATE ${headers} <QTest>)
endfunction()
