# Checks that no function body in app/ is longer than LIMIT lines (60
# unless given): a longer one is asking to be split into named steps.
#
#   cmake -P cmake/CheckFunctionLength.cmake              (the source tree)
#   cmake -DROOT=DIR [-DLIMIT=N] -P cmake/CheckFunctionLength.cmake
#
# clang-format (.clang-format) puts a function's braces alone at the start
# of a line and a lambda's or a namespace's elsewhere, so a body is a "{"
# line up to the next line that starts with "}"; its length is the lines
# between them. A class written the same way ("class X", "struct X" on the
# line that opens it) is not a function. Prints each breach as
# FILE:LINE (its opening brace): N lines, SIGNATURE (its first line) and
# fails when there is one. Registered with CTest as unit.functionlength;
# unit.functionlengthplanted plants a long function in a scratch tree and
# expects it caught.
cmake_minimum_required(VERSION 3.19)
if(NOT ROOT)
  set(ROOT "${CMAKE_CURRENT_LIST_DIR}/..")
endif()
if(NOT LIMIT)
  set(LIMIT 60)
endif()
get_filename_component(root "${ROOT}" ABSOLUTE)

# The number of "\n" in TEXT.
function(count_lines text out)
  string(REGEX REPLACE "[^\n]" "" newlines "${text}")
  string(LENGTH "${newlines}" n)
  set(${out} ${n} PARENT_SCOPE)
endfunction()

# Appends FILE's breaches to `breaches` in the caller's scope.
function(check_file path relative)
  file(READ "${path}" text)
  # Semicolons would split CMake lists. The "\n" in front makes a brace on
  # the first line findable; `text` begins at line line_base (0: that "\n").
  string(REPLACE ";" "," text "\n${text}")
  set(found "")
  set(line_base 0)
  while(TRUE)
    string(FIND "${text}" "\n{\n" open)
    if(open EQUAL -1)
      break()
    endif()
    string(SUBSTRING "${text}" 0 ${open} before)
    math(EXPR body_start "${open} + 3")
    string(SUBSTRING "${text}" ${body_start} -1 rest)
    string(FIND "\n${rest}" "\n}" close)
    if(close EQUAL -1)
      break()
    endif()
    string(SUBSTRING "\n${rest}" 0 ${close} body)
    count_lines("${before}" before_lines)
    count_lines("${body}" body_lines)
    math(EXPR brace_line "${line_base} + ${before_lines} + 1")
    # The signature's first line: the last of `before` not indented.
    # (The pattern is unambiguous, so CMake's backtracking stays linear.)
    string(REGEX MATCH "\n([^ \n][^\n]*)(\n +[^ \n][^\n]*)*$" signature "${before}")
    set(signature "${CMAKE_MATCH_1}")
    if(body_lines GREATER LIMIT AND NOT signature MATCHES "^(template *<.*> *)?(class|struct|union|enum) ")
      list(APPEND found "${relative}:${brace_line}: ${body_lines} lines, ${signature}")
    endif()
    math(EXPR line_base "${brace_line} + 1 + ${body_lines}")
    math(EXPR after "${close} + 1")
    string(SUBSTRING "\n${rest}" ${after} -1 text)
  endwhile()
  set(breaches ${breaches} ${found} PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE sources RELATIVE "${root}" "${root}/app/*.cpp" "${root}/app/*.h")
list(SORT sources)
set(breaches "")
foreach(relative IN LISTS sources)
  check_file("${root}/${relative}" "${relative}")
endforeach()

list(LENGTH sources checked)
if(breaches)
  list(LENGTH breaches n)
  list(JOIN breaches "\n" listing)
  message(FATAL_ERROR "${n} function(s) over ${LIMIT} lines:\n${listing}")
endif()
message(STATUS "${checked} files, no function over ${LIMIT} lines")
