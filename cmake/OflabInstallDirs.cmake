# Where `cmake --install` puts things (GNU layout under the prefix), set before the targets
# so that the programs can find their installed datasets relative to their own location.
include(GNUInstallDirs)
set(OFLAB_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/oflab")  # datasets/ and manual/
set(OFLAB_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/oflab")  # the core headers
set(OFLAB_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/oflab")  # oflabConfig.cmake
# From bin/ to the datasets, e.g. "../share/oflab/datasets" (formats/datasets.cpp).
file(RELATIVE_PATH OFLAB_INSTALL_DATASETS_RELATIVE "/prefix/${CMAKE_INSTALL_BINDIR}"
     "/prefix/${OFLAB_INSTALL_DATADIR}/datasets")
