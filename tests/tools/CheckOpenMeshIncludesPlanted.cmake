# unit.openmeshincludesplanted: cmake/CheckOpenMeshIncludes.cmake catches an
# OpenMesh header included directly, at its line, and lets pass the wrapper
# itself and the version header.
#
#   cmake -DROOT=<source tree> -DWORK=<scratch folder> -P CheckOpenMeshIncludesPlanted.cmake
cmake_minimum_required(VERSION 3.19)

file(REMOVE_RECURSE "${WORK}")
file(COPY "${ROOT}/app/mesh/import/OpenMeshHeaders.h" DESTINATION "${WORK}/app/mesh/import")
# The direct include on line 4; the version header on line 2 may stay.
file(WRITE "${WORK}/app/planted/Planted.cpp"
     "// planted; a semicolon [ and a bracket do not shift the lines\n"
     "#include <OpenMesh/Core/System/config.h>\n"
     "#include \"mesh/import/OpenMeshHeaders.h\"\n"
     "#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>\n")
include(${CMAKE_CURRENT_LIST_DIR}/ExpectCaught.cmake)
expect_caught(${ROOT}/cmake/CheckOpenMeshIncludes.cmake "a direct OpenMesh include"
              "1 include(s) of OpenMesh"
              "app/planted/Planted.cpp:4: #include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>")
