# `cpack -G DEB` (scripts/package.sh): a Debian 12 package of what
# cmake/Install.cmake installs, under /usr. Library dependencies come from
# dpkg-shlibdeps; the Mesa drivers that Qt and EGL open at run time are
# named here because no binary links them.
set(CPACK_PACKAGE_NAME "phonglab")
set(CPACK_PACKAGE_VENDOR "The PhongLab developers")
set(CPACK_PACKAGE_CONTACT "The PhongLab developers <phonglab@phonglab.org>")
set(CPACK_PACKAGE_HOMEPAGE_URL "${PHONGLAB_HOMEPAGE}")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "shader editor and playground for the Phong illumination model")
set(CPACK_PACKAGE_DESCRIPTION
    "PhongLab edits GLSL lighting shaders live on real meshes and checks every\n"
    "pixel against an exact double-precision CPU reference. When an image is\n"
    "wrong it names the classic mistake that explains it; the pixel inspector\n"
    "shows each term of the Phong equation. The commands render, check,\n"
    "mesh-info and bench run without a display server.")
string(JOIN "" CPACK_PACKAGE_DESCRIPTION ${CPACK_PACKAGE_DESCRIPTION})
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR "DEB")

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # phonglab_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_SECTION "graphics")
set(CPACK_DEBIAN_PACKAGE_PRIORITY "optional")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Mesa's GL and EGL drivers are loaded through glvnd, not linked.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libgl1-mesa-dri, libegl-mesa0, libglx-mesa0")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

include(CPack)
