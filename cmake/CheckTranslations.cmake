# unit.translations: every translation is complete and matches the code.
#   cmake -DLUPDATE=<lupdate> -DSOURCES=<list file> -DWORK=<dir> -DINCLUDE=<app dir>
#         -P CheckTranslations.cmake <ts>...
# INCLUDE is where "core/..." includes resolve, as for update_translations:
# lupdate reads the headers a file includes to know the contexts of its
# tr() calls, and without them names some by their struct instead.
# Fails when a .ts file has an entry that is unfinished or obsolete, or when
# lupdate run over the sources now (into a copy) finds a string the .ts
# lacks (new, so unfinished) or one the code no longer has (vanished). Each
# is named, with its context, so that the fix is one lupdate and a
# translation away (`cmake --build build --target update_translations`).

# The messages of `file` whose translation carries `type="..."` (one of
# unfinished, vanished, obsolete), as "context: source" lines in `out`.
function(flagged_messages file out)
  file(READ "${file}" text)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "<context>" ";<context>" contexts "${text}")
  set(found "")
  foreach(context IN LISTS contexts)
    if(NOT context MATCHES "<name>([^<]*)</name>")
      continue()
    endif()
    set(name "${CMAKE_MATCH_1}")
    string(REPLACE "<message" ";<message" messages "${context}")
    foreach(message IN LISTS messages)
      if(message MATCHES "<source>([^<]*)</source>"
         AND message MATCHES "type=\"(unfinished|vanished|obsolete)\"")
        string(REGEX MATCH "<source>([^<]*)</source>" _ "${message}")
        set(source "${CMAKE_MATCH_1}")
        string(REGEX MATCH "type=\"([a-z]+)\"" _ "${message}")
        string(REPLACE "<semicolon>" ";" source "${source}")
        string(APPEND found "  ${CMAKE_MATCH_1}: ${name}: ${source}\n")
      endif()
    endforeach()
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

set(problems "")
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(NOT CMAKE_ARGV${i} MATCHES "\\.ts$")
    continue()
  endif()
  set(ts "${CMAKE_ARGV${i}}")
  get_filename_component(name "${ts}" NAME)
  flagged_messages("${ts}" committed)
  if(committed)
    string(APPEND problems "${ts} has entries to finish or drop:\n${committed}")
  endif()
  file(MAKE_DIRECTORY "${WORK}")
  configure_file("${ts}" "${WORK}/${name}" COPYONLY)
  set(include_args "")
  if(INCLUDE)
    set(include_args "-I${INCLUDE}")
  endif()
  execute_process(COMMAND "${LUPDATE}" -locations none ${include_args} "@${SOURCES}"
                          -ts "${WORK}/${name}"
                  RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "lupdate failed on ${ts}:\n${log}")
  endif()
  flagged_messages("${WORK}/${name}" now)
  if(now)
    string(APPEND problems
           "${ts} does not match the code (unfinished: a string it lacks; vanished: one the "
           "code no longer has):\n${now}")
  endif()
endforeach()
if(problems)
  message(FATAL_ERROR "${problems}")
endif()
message(STATUS "translations: complete and in step with the code")
