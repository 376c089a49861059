# The layers of app/ and the rooms inside them, with the direction between
# them: the one list that the libraries' links (app/CMakeLists.txt), their
# precompiled headers (cmake/BuildSpeed.cmake), what a test links
# (tests/CMakeLists.txt) and unit.layers (cmake/CheckLayers.cmake) read.
# docs/architecture.md says what each holds.
#
#   PHONGLAB_LAYERS              every layer, each after the layers it uses
#   PHONGLAB_USES_<layer>        the layers it links directly; its files may
#                                include from these and from what they use
#   PHONGLAB_ROOMS_<layer>       its rooms (folders), lowest first: a file of
#                                a room includes from its own room and the
#                                rooms before it, never from one after it.
#                                A layer with rooms has no file outside them.
#   PHONGLAB_QT_<layer>          the Qt it may use: core (Qt Core alone: no
#                                images, no GL), gui (no widgets) or widgets
#   PHONGLAB_PCH_<layer>         the precompiled headers of its library:
#                                core, render or ui (cmake/BuildSpeed.cmake)
#   PHONGLAB_TEST_GROUP_<layer>  the Qt modules a test linking it gets, for
#                                the tests' shared precompiled headers:
#                                core < render < bench < charts < ui
#
# Usable from a script (cmake -P) and from the build alike: it only sets
# variables and defines functions.

set(PHONGLAB_LAYERS headless core mesh render bench charts ui cli benchcli)

set(PHONGLAB_USES_headless "")
set(PHONGLAB_USES_core "")
set(PHONGLAB_USES_mesh core)
set(PHONGLAB_USES_render mesh headless)
set(PHONGLAB_USES_bench render)
set(PHONGLAB_USES_charts bench)
set(PHONGLAB_USES_ui render bench charts)
set(PHONGLAB_USES_cli render bench)
set(PHONGLAB_USES_benchcli cli charts)

# core: support is the floor; program is the vocabulary of a shader program
# (stages, dialect, bindings, the course's prelude, tokens, lint); project
# reads a WebGL project's pages; session keeps the editors across a crash;
# view is the camera; scene what a scene file holds; reference the exact
# image; check judges programs and images; page runs a student's page.
set(PHONGLAB_ROOMS_core support program project session view scene reference check page)
# mesh: import reads files; detail lowers a mesh's triangle count; normals
# builds the GPU-ready mesh; loading puts the three together for a scene (the
# import child, the cache).
set(PHONGLAB_ROOMS_mesh import detail normals loading)
# render: gl is the context and GL objects; program builds programs; draw
# draws scenes; check draws what a check needs; page replays a page's draws.
set(PHONGLAB_ROOMS_render gl program draw check page)
# ui: the window stands on every dock and dialog.
set(PHONGLAB_ROOMS_ui viewport shaders uniforms scene check performance help window)
# cli: common to every command; one room per command family; dispatch picks
# the command.
set(PHONGLAB_ROOMS_cli common mesh render page check grade dispatch)

foreach(layer IN ITEMS headless render bench cli)
  set(PHONGLAB_QT_${layer} gui)
endforeach()
foreach(layer IN ITEMS core mesh)
  set(PHONGLAB_QT_${layer} core)
endforeach()
foreach(layer IN ITEMS charts ui benchcli)
  set(PHONGLAB_QT_${layer} widgets)
endforeach()

set(PHONGLAB_PCH_core core)
set(PHONGLAB_PCH_mesh core)
set(PHONGLAB_PCH_render render)
set(PHONGLAB_PCH_bench render)
set(PHONGLAB_PCH_cli render)
set(PHONGLAB_PCH_charts ui)
set(PHONGLAB_PCH_ui ui)
set(PHONGLAB_PCH_benchcli ui)
# headless has none: Qt's private platform headers, in a handful of files.

set(PHONGLAB_TEST_GROUPS core render bench charts ui)
set(PHONGLAB_TEST_GROUP_headless render)
set(PHONGLAB_TEST_GROUP_core core)
set(PHONGLAB_TEST_GROUP_mesh core)
set(PHONGLAB_TEST_GROUP_render render)
set(PHONGLAB_TEST_GROUP_bench bench)
set(PHONGLAB_TEST_GROUP_cli bench)
set(PHONGLAB_TEST_GROUP_charts charts)
set(PHONGLAB_TEST_GROUP_benchcli charts)
set(PHONGLAB_TEST_GROUP_ui ui)

# Rules a room keeps besides its direction, as ROOM "INCLUDE REGEX" "WHY":
# an include of a file of app/ROOM/ matching the regex is refused.
set(PHONGLAB_ROOM_RULES
  # A check gets its scene already read, which is what lets the window, the
  # CLI and the grader hand it the same Scene.
  "core/check" "^core/scene/(SceneJson[A-Za-z]*|ScenePaths)\\.h$" "check/ does not read scene files")

# The layers `layer` may include from: itself and everything below it.
function(phonglab_layer_reach layer out_var)
  set(reach ${layer})
  set(queue ${PHONGLAB_USES_${layer}})
  while(queue)
    list(POP_FRONT queue next)
    if(NOT next IN_LIST reach)
      list(APPEND reach ${next})
      list(APPEND queue ${PHONGLAB_USES_${next}})
    endif()
  endwhile()
  set(${out_var} ${reach} PARENT_SCOPE)
endfunction()
