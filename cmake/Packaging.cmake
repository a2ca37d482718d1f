# SPDX-License-Identifier: GPL-3.0-or-later
# The Debian package: `cd build && cpack -G DEB` writes
# gridfree_<version>_<arch>.deb, installing under /usr what `cmake --install`
# installs (cmake/Install.cmake). Depends is computed by dpkg-shlibdeps from
# what the two executables link (libsqlite3, libspdlog, libfmt, libfftw3,
# libgomp, libstdc++...); the programs gridfree only runs when present are
# Recommends (rsvg-convert for the charts' PDF/PNG copies, man) or Suggests
# (Slurm's commands, OpenFOAM for the external studies, Lmod).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME gridfree)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "The gridfree developers")
set(CPACK_PACKAGE_CONTACT "The gridfree developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "grid-free extrapolation and numerical uncertainty of CFD-DEM results")
set(CPACK_PACKAGE_DESCRIPTION
    "gridfree freezes a particle configuration, solves the steady gas flow through it on many grids, and extrapolates the pressure drop to the grid-free limit with an uncertainty for every grid (Fullmer & Musser 2018). Studies run on a workstation or through Slurm; results go to one SQLite database and HTML/Markdown reports.")
set(CPACK_RESOURCE_FILE_LICENSE ${CMAKE_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "librsvg2-bin, man-db")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "slurm-client, openfoam, lmod, bash-completion")
include(CPack)
