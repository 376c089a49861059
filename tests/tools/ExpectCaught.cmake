# What the planted-breach scripts share: run a tree check on the scratch
# tree WORK and expect it to fail, saying each of the given texts.
#
#   include(ExpectCaught.cmake)
#   expect_caught(<check script> <what was planted> <expected text>...)
function(expect_caught checker planted)
  execute_process(COMMAND ${CMAKE_COMMAND} -DROOT=${WORK} -P ${checker}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(text "${out}${err}")
  if(rc EQUAL 0)
    message(FATAL_ERROR "${planted} was not caught:\n${text}")
  endif()
  foreach(expected IN LISTS ARGN)
    string(FIND "${text}" "${expected}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "the check did not say \"${expected}\":\n${text}")
    endif()
  endforeach()
  message(STATUS "caught: ${text}")
endfunction()
