# `cmake --install`: the app as a desktop application under one prefix.
#
#   bin/phonglab
#   share/phonglab/{shaders,assets}       found relative to bin/ (ResourcePaths)
#   share/applications, icons, metainfo, mime/packages, man/man1
#   share/doc/phonglab                    README, docs/, copyright, changelog
#
# Nothing installed names a path of the build or source tree, so a moved
# prefix works (tests/install/InstallTest.cmake checks it).

include(GNUInstallDirs)
# GNUInstallDirs names the doc folder after the project ("PhongLab"); Debian
# and the app's docs locator expect the package's name.
set(PHONGLAB_DOC_DIR "${CMAKE_INSTALL_DATADIR}/doc/phonglab")

set(PHONGLAB_APP_ID "org.phonglab.PhongLab")
set(PHONGLAB_HOMEPAGE "https://phonglab.org" CACHE STRING "Project homepage (metainfo, package)")
set(PHONGLAB_PACKAGING_DIR "${PROJECT_SOURCE_DIR}/packaging")
set(PHONGLAB_DATA_DIR "${CMAKE_INSTALL_DATADIR}/phonglab")

# The Debian changelog is where a release is written down: its newest entry
# must be this project's version, and its date is the metainfo's release date.
file(STRINGS "${PHONGLAB_PACKAGING_DIR}/debian/changelog" changelog_lines)
list(GET changelog_lines 0 changelog_head)
if(NOT changelog_head MATCHES "^phonglab \\(([^)]+)\\)")
  message(FATAL_ERROR "packaging/debian/changelog: first line is not 'phonglab (VERSION) ...'")
endif()
if(NOT CMAKE_MATCH_1 STREQUAL PROJECT_VERSION)
  message(FATAL_ERROR "packaging/debian/changelog's newest entry is ${CMAKE_MATCH_1}, "
                      "the project is ${PROJECT_VERSION}: add an entry for the release")
endif()
foreach(line IN LISTS changelog_lines)
  if(line MATCHES "^ -- .*  [A-Z][a-z][a-z], ([0-9]+) ([A-Z][a-z][a-z]) ([0-9][0-9][0-9][0-9])")
    set(day "${CMAKE_MATCH_1}")
    set(month_name "${CMAKE_MATCH_2}")
    set(year "${CMAKE_MATCH_3}")
    break()
  endif()
endforeach()
set(months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
list(FIND months "${month_name}" month)
if(NOT DEFINED year OR month EQUAL -1)
  message(FATAL_ERROR "packaging/debian/changelog: no dated trailer line (' -- NAME <MAIL>  DATE')")
endif()
math(EXPR month "${month} + 1" OUTPUT_FORMAT DECIMAL)
string(LENGTH "${day}" day_length)
if(day_length EQUAL 1)
  set(day "0${day}")
endif()
if(month LESS 10)
  set(month "0${month}")
endif()
set(PHONGLAB_RELEASE_DATE "${year}-${month}-${day}")

configure_file("${PHONGLAB_PACKAGING_DIR}/${PHONGLAB_APP_ID}.metainfo.xml.in"
               "${PROJECT_BINARY_DIR}/packaging/${PHONGLAB_APP_ID}.metainfo.xml" @ONLY)

# Debian wants the man page and the changelog compressed, reproducibly (-n:
# no name or time stamp in the header).
find_program(GZIP_EXECUTABLE gzip REQUIRED)
set(man_gz "${PROJECT_BINARY_DIR}/packaging/phonglab.1.gz")
set(changelog_gz "${PROJECT_BINARY_DIR}/packaging/changelog.gz")
add_custom_command(OUTPUT "${man_gz}"
  COMMAND ${GZIP_EXECUTABLE} -9n -c "${PHONGLAB_PACKAGING_DIR}/phonglab.1" > "${man_gz}"
  DEPENDS "${PHONGLAB_PACKAGING_DIR}/phonglab.1" VERBATIM)
add_custom_command(OUTPUT "${changelog_gz}"
  COMMAND ${GZIP_EXECUTABLE} -9n -c "${PHONGLAB_PACKAGING_DIR}/debian/changelog" > "${changelog_gz}"
  DEPENDS "${PHONGLAB_PACKAGING_DIR}/debian/changelog" VERBATIM)
add_custom_target(phonglab_packaging_files ALL DEPENDS "${man_gz}" "${changelog_gz}")

install(TARGETS phonglab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY "${PROJECT_SOURCE_DIR}/shaders/" DESTINATION "${PHONGLAB_DATA_DIR}/shaders"
  FILES_MATCHING PATTERN "*.vert" PATTERN "*.frag")
# The meshes and scenes; the Blender scripts that made the meshes stay in
# the source.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/assets/meshes" "${PROJECT_SOURCE_DIR}/assets/scenes"
  DESTINATION "${PHONGLAB_DATA_DIR}/assets")
install(FILES "${PHONGLAB_PACKAGING_DIR}/${PHONGLAB_APP_ID}.desktop"
  DESTINATION "${CMAKE_INSTALL_DATADIR}/applications")
install(FILES "${PHONGLAB_PACKAGING_DIR}/${PHONGLAB_APP_ID}.svg"
  DESTINATION "${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps")
install(FILES "${PROJECT_BINARY_DIR}/packaging/${PHONGLAB_APP_ID}.metainfo.xml"
  DESTINATION "${CMAKE_INSTALL_DATADIR}/metainfo")
install(FILES "${PHONGLAB_PACKAGING_DIR}/${PHONGLAB_APP_ID}.mime.xml"
  DESTINATION "${CMAKE_INSTALL_DATADIR}/mime/packages" RENAME "${PHONGLAB_APP_ID}.xml")
install(FILES "${man_gz}" DESTINATION "${CMAKE_INSTALL_MANDIR}/man1")
install(FILES "${PROJECT_SOURCE_DIR}/README.md" "${changelog_gz}"
  DESTINATION "${PHONGLAB_DOC_DIR}")
install(FILES "${PHONGLAB_PACKAGING_DIR}/debian/copyright" DESTINATION "${PHONGLAB_DOC_DIR}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/docs" DESTINATION "${PHONGLAB_DOC_DIR}")
