# Checks that the man page documents the command line as built: every command
# that `phonglab --help` lists and every --long-option that a command's
# --help prints.
#
#   cmake -DPHONGLAB_EXE=build/app/phonglab -DMAN_PAGE=packaging/phonglab.1 \
#         -P cmake/CheckManPage.cmake
#
# The commands are the lines under "commands:" in `phonglab --help`; the
# options are the --tokens of `phonglab --help` and of `phonglab CMD --help`.
# The man page is read as roff source with `\-` taken as `-` and the
# zero-width escapes (\& \% \:) and font changes (\fB ...) dropped. Each
# command must have its own subsection (`.SS CMD`) and each of its options
# must appear in that subsection; the options of `phonglab --help` may appear
# anywhere. The page must also have an EXIT STATUS section. Fails naming
# everything missing. Registered with CTest by tests/CMakeLists.txt.
cmake_minimum_required(VERSION 3.16)

foreach(var PHONGLAB_EXE MAN_PAGE)
  if(NOT ${var})
    message(FATAL_ERROR "pass -D${var}=... (see the head of ${CMAKE_CURRENT_LIST_FILE})")
  endif()
endforeach()
if(NOT EXISTS "${MAN_PAGE}")
  message(FATAL_ERROR "no man page at ${MAN_PAGE}")
endif()

# `phonglab ARGS --help`'s output; fails unless it exits 0.
function(help_text out_var)
  execute_process(COMMAND "${PHONGLAB_EXE}" ${ARGN} --help
                  OUTPUT_VARIABLE text ERROR_VARIABLE errors RESULT_VARIABLE status
                  TIMEOUT 120)
  if(NOT status STREQUAL "0")
    string(JOIN " " shown ${ARGN})
    message(FATAL_ERROR "'${PHONGLAB_EXE} ${shown} --help' failed (${status}):\n${errors}")
  endif()
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

# The distinct --long-options in TEXT, sorted.
function(long_options out_var text)
  string(REGEX MATCHALL "--[A-Za-z0-9][A-Za-z0-9-]*" tokens "${text}")
  set(options "")
  foreach(token IN LISTS tokens)
    string(REGEX REPLACE "-+$" "" token "${token}") # a hyphen ending a sentence
    list(APPEND options "${token}")
  endforeach()
  list(REMOVE_DUPLICATES options)
  list(SORT options)
  set(${out_var} "${options}" PARENT_SCOPE)
endfunction()

# Whether OPTION occurs in TEXT as a whole word (--size, not --size-limit).
function(has_option out_var text option)
  string(REGEX REPLACE "([][+.*?^$()|\\\\])" "\\\\\\1" pattern "${option}")
  if(text MATCHES "(^|[^A-Za-z0-9-])${pattern}([^A-Za-z0-9-]|$)")
    set(${out_var} TRUE PARENT_SCOPE)
  else()
    set(${out_var} FALSE PARENT_SCOPE)
  endif()
endfunction()

# The man page as plain-ish text: \- is a hyphen; \& \% \: and font
# changes print nothing.
file(READ "${MAN_PAGE}" page)
string(REPLACE "\\-" "-" page "${page}")
string(REPLACE "\\&" "" page "${page}")
string(REPLACE "\\%" "" page "${page}")
string(REPLACE "\\:" "" page "${page}")
# Font changes (\fB \fI \fR \fP \f(CW \f[CB]) print nothing either.
string(REGEX REPLACE "\\\\f(\\[[^]]*\\]|\\(..|.)" "" page "${page}")
# Lines as a list. CMake's list syntax would join lines at a ; inside
# unbalanced [ ] or after a \, so those become placeholders first.
function(split_lines out_var text)
  string(REPLACE "\\" "<backslash>" text "${text}")
  string(REPLACE "[" "<lbracket>" text "${text}")
  string(REPLACE "]" "<rbracket>" text "${text}")
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "\n" ";" text "${text}")
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()
split_lines(page_lines "${page}")

# The commands: `  NAME  summary` lines from "commands:" to the next blank line.
help_text(main_help)
split_lines(main_lines "${main_help}")
set(commands "")
set(in_commands FALSE)
foreach(line IN LISTS main_lines)
  if(line MATCHES "^commands:")
    set(in_commands TRUE)
  elseif(in_commands AND line MATCHES "^[ \t]*$")
    set(in_commands FALSE)
  elseif(in_commands AND line MATCHES "^[ \t]+([a-z][a-z0-9-]*)")
    list(APPEND commands "${CMAKE_MATCH_1}")
  endif()
endforeach()
if(NOT commands)
  message(FATAL_ERROR "'${PHONGLAB_EXE} --help' lists no commands under \"commands:\":\n${main_help}")
endif()

set(missing "")
set(checked 0)

if(NOT page MATCHES "(^|\n)\\.SH[ \t]+\"?EXIT STATUS\"?[ \t]*(\n|$)")
  list(APPEND missing "the EXIT STATUS section (.SH \"EXIT STATUS\")")
endif()

long_options(main_options "${main_help}")
foreach(option IN LISTS main_options)
  has_option(found "${page}" "${option}")
  math(EXPR checked "${checked} + 1")
  if(NOT found)
    list(APPEND missing "${option} (phonglab --help)")
  endif()
endforeach()

foreach(command IN LISTS commands)
  # The command's subsection: from `.SS COMMAND` to the next .SS or .SH.
  set(section "")
  set(in_section FALSE)
  set(has_section FALSE)
  foreach(line IN LISTS page_lines)
    if(line MATCHES "^\\.S[SH][ \t]")
      set(in_section FALSE)
      if(line MATCHES "^\\.SS[ \t]+\"?([^\"]*)\"?[ \t]*$" AND CMAKE_MATCH_1 STREQUAL command)
        set(in_section TRUE)
        set(has_section TRUE)
      endif()
    elseif(in_section)
      string(APPEND section "${line}\n")
    endif()
  endforeach()
  if(NOT has_section)
    list(APPEND missing "command ${command} (no .SS ${command} subsection)")
    continue()
  endif()

  help_text(command_help "${command}")
  long_options(options "${command_help}")
  foreach(option IN LISTS options)
    has_option(found "${section}" "${option}")
    math(EXPR checked "${checked} + 1")
    if(NOT found)
      list(APPEND missing "${option} (phonglab ${command} --help)")
    endif()
  endforeach()
endforeach()

if(missing)
  list(LENGTH missing count)
  list(JOIN missing "\n  " shown)
  message(FATAL_ERROR "${MAN_PAGE} lacks ${count} thing(s) the program has:\n  ${shown}")
endif()
list(JOIN commands ", " command_list)
message(STATUS "man page: commands ${command_list}, ${checked} options and EXIT STATUS all documented")
