# unit.functionlengthplanted: cmake/CheckFunctionLength.cmake catches a
# function one line over the limit, at its line, and lets pass one at the
# limit and a long class written with its brace on a line of its own.
#
#   cmake -DROOT=<source tree> -DWORK=<scratch folder> -P CheckFunctionLengthPlanted.cmake
cmake_minimum_required(VERSION 3.19)

# A function called NAME whose body is N lines.
function(function_text name n out)
  set(text "int ${name}(int x,\n         int y)\n{\n")
  foreach(i RANGE 1 ${n})
    string(APPEND text "    x += y; // ${i}\n")
  endforeach()
  set(${out} "${text}}\n" PARENT_SCOPE)
endfunction()

function_text(atTheLimit 60 at_limit)
function_text(oneOver 61 one_over)
set(long_class "class Long\n{\n")
foreach(i RANGE 1 80)
  string(APPEND long_class "    int m${i} = 0;\n")
endforeach()
string(APPEND long_class "};\n")

file(REMOVE_RECURSE "${WORK}")
# atTheLimit's brace on line 4, Long's on 68, oneOver's on 153.
file(WRITE "${WORK}/app/planted/Long.cpp"
     "// planted\n${at_limit}\n${long_class}\n${one_over}")
include(${CMAKE_CURRENT_LIST_DIR}/ExpectCaught.cmake)
expect_caught(${ROOT}/cmake/CheckFunctionLength.cmake "a function of 61 lines"
              "1 function(s) over 60 lines"
              "app/planted/Long.cpp:153: 61 lines, int oneOver")
