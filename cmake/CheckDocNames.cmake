# Checks that every PhongLab name docs/architecture.md cites exists: each
# `folder/File` path (app/<layer>/..., shaders/, scripts/, tests/, cmake/,
# packaging/) is a file or folder, and each identifier written in
# backticks (CamelCase, camelCase, Class::member, PHONGLAB_* variables) is
# an identifier of the sources. A page a newcomer follows must not send
# them to something that was renamed or removed.
#
#   cmake -DROOT=. -P cmake/CheckDocNames.cmake   [-DDOC=docs/architecture.md]
#
# Registered with CTest as unit.architecturenames.
cmake_minimum_required(VERSION 3.16)
if(NOT ROOT)
  set(ROOT "${CMAKE_CURRENT_LIST_DIR}/..")
endif()
get_filename_component(ROOT "${ROOT}" ABSOLUTE)
if(NOT DOC)
  set(DOC "${ROOT}/docs/architecture.md")
endif()

# Every identifier of the sources, once.
file(GLOB_RECURSE sources
  "${ROOT}/app/*.h" "${ROOT}/app/*.cpp" "${ROOT}/tests/*.h" "${ROOT}/tests/*.cpp"
  "${ROOT}/tests/*.txt" "${ROOT}/cmake/*.cmake" "${ROOT}/scripts/*.sh"
  "${ROOT}/shaders/*.vert" "${ROOT}/shaders/*.frag" "${ROOT}/CMakeLists.txt")
set(identifiers "")
foreach(source IN LISTS sources)
  file(READ "${source}" text)
  string(REGEX MATCHALL "[A-Za-z_][A-Za-z0-9_]*" words "${text}")
  list(APPEND identifiers ${words})
  list(REMOVE_DUPLICATES identifiers)
  get_filename_component(base "${source}" NAME_WE) # "SceneJsonWrite.cpp" names a file
  list(APPEND identifiers "${base}")
endforeach()

file(READ "${DOC}" doc)
# A page a newcomer reads in one sitting: past this it is a reference
# nobody reads, and what it says stops being checked by reading.
set(max_lines 350)
string(REGEX REPLACE "[^\n]" "" newlines "${doc}")
string(LENGTH "${newlines}" line_count)
string(REGEX MATCHALL "`[^`\n]+`" spans "${doc}")
set(missing "")
set(checked 0)
foreach(span IN LISTS spans)
  string(REGEX REPLACE "^`|`$" "" span "${span}")
  # Paths.
  string(REGEX MATCHALL
    "(app/)?(core|mesh|render|bench|charts|ui|cli|benchcli|headless|shaders|scripts|tests|cmake|packaging)/[A-Za-z0-9_./-]*[A-Za-z0-9_]"
    paths "${span}")
  foreach(path IN LISTS paths)
    if(path MATCHES "^(core|mesh|render|bench|charts|ui|cli|benchcli|headless)/")
      set(path "app/${path}")
    endif()
    math(EXPR checked "${checked} + 1")
    file(GLOB stems "${ROOT}/${path}.*") # shaders/marker.* names both stages
    if(NOT EXISTS "${ROOT}/${path}" AND NOT stems)
      list(APPEND missing "${path} (no such file)")
    endif()
  endforeach()
  string(REGEX REPLACE "(app/)?[a-z]+/[A-Za-z0-9_./-]*" "" span "${span}")
  string(REGEX REPLACE "Q[A-Za-z0-9]+::[A-Za-z_]+" "" span "${span}") # Qt's members
  # Identifiers: CamelCase or camelCase words and PHONGLAB_ variables.
  string(REGEX MATCHALL "[A-Za-z_][A-Za-z0-9_]*" words "${span}")
  foreach(word IN LISTS words)
    if(word MATCHES "^Q[A-Z]" OR word MATCHES "^gl[A-Z]" OR word MATCHES "^GL_")
      continue() # Qt's and OpenGL's own
    endif()
    if(word MATCHES "^[A-Z][a-z0-9]+[A-Z]" OR word MATCHES "^[a-z]+[A-Z]"
       OR word MATCHES "^PHONGLAB_")
      math(EXPR checked "${checked} + 1")
      list(FIND identifiers "${word}" found)
      if(found EQUAL -1)
        list(APPEND missing "${word}")
      endif()
    endif()
  endforeach()
endforeach()
# Rooms: every room cmake/Layers.cmake lists is named as `LAYER/ROOM/`
# (those of app/ui as `ROOM/`), and so is every folder of app/; and every header of app/ is named, by
# itself (`Viewport`) or at the end of a path (`ui/viewport/Viewport`). A
# room or a class a newcomer cannot find on the page is one nobody keeps
# tidy.
file(GLOB rooms LIST_DIRECTORIES true "${ROOT}/app/*/*")
foreach(room IN LISTS rooms)
  if(NOT IS_DIRECTORY "${room}")
    continue()
  endif()
  get_filename_component(name "${room}" NAME)
  get_filename_component(parent "${room}" DIRECTORY)
  get_filename_component(layer "${parent}" NAME)
  math(EXPR checked "${checked} + 1")
  if(layer STREQUAL "ui")
    set(spelled "${name}/")
  else()
    set(spelled "${layer}/${name}/")
  endif()
  string(FIND "${doc}" "`${spelled}`" at)
  if(at EQUAL -1)
    list(APPEND missing "${layer}/${name}/ (a room of app/${layer} the page does not name)")
  endif()
endforeach()
file(GLOB_RECURSE headers RELATIVE "${ROOT}/app" "${ROOT}/app/*.h")
foreach(header IN LISTS headers)
  get_filename_component(stem "${header}" NAME_WE)
  math(EXPR checked "${checked} + 1")
  set(named FALSE)
  foreach(form "`${stem}`" "/${stem}`" "`${stem}.h`" "/${stem}.h`")
    string(FIND "${doc}" "${form}" at)
    if(at GREATER -1)
      set(named TRUE)
      break()
    endif()
  endforeach()
  if(NOT named)
    list(APPEND missing "app/${header} (a header the page does not name)")
  endif()
endforeach()
if(line_count GREATER max_lines)
  list(APPEND missing "${DOC} has ${line_count} lines, over ${max_lines}")
endif()
list(REMOVE_DUPLICATES missing)
if(missing)
  string(REPLACE ";" "\n  " shown "${missing}")
  message(FATAL_ERROR "${DOC} cites names the sources do not have:\n  ${shown}")
endif()
message(STATUS "${DOC}: all ${checked} names it cites exist")
