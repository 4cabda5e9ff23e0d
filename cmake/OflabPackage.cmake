# The Debian package (CPack DEB): `cpack -G DEB` in the build tree, or tools/make-deb.sh,
# gives oflab_<version>_amd64.deb installing under /usr. Depends is computed from the
# programs' shared libraries by dpkg-shlibdeps (VTK, Qt 5, FFmpeg's libraries, giflib,
# ...), so it names exactly the runtime packages the binaries link. See manual/install.md.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME oflab)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "the oflab authors")
set(CPACK_PACKAGE_CONTACT "oflab maintainers <maintainers@oflab.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Optic Flow Lab: see, teach and measure image-based animation with optic flow")
set(CPACK_PACKAGE_DESCRIPTION
    "A desktop tool (oflab) and a command-line tool (oflab-cli) for the optic flow of a moving
textured plane and the reuse of its previous image through a 2D warp (no update,
translate, affine, perspective, re-render). Includes the core library with its headers
and CMake package (find_package(oflab), target oflab::core), and the Python module
oflab (import oflab: runs, flows and lessons as dicts and numpy arrays).")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # oflab_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The window renders with OpenGL: Mesa's drivers on machines without a vendor driver.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libgl1-mesa-dri")
# Linking the installed core library from CMake needs GLM's headers and config.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libglm-dev, cmake, g++")
# The Python module (python/CMakeLists.txt): its interpreter and numpy, which
# dpkg-shlibdeps cannot see (added to what it computes).
get_property(oflab_python_depends GLOBAL PROPERTY OFLAB_PYTHON_DEB_DEPENDS)
if(oflab_python_depends)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${oflab_python_depends}")
endif()
set(CPACK_OUTPUT_FILE_PREFIX ${CMAKE_BINARY_DIR}/packages)
include(CPack)
