# SPDX-License-Identifier: GPL-3.0-or-later
# `cmake --install build --prefix P` (or `make install PREFIX=P`) lays out:
#   P/bin/gridfree, P/bin/gridfree-worker   (gridfree runs the worker beside itself)
#   P/share/gridfree/studies/               (the example studies and their templates)
#   P/share/doc/gridfree/                   (README, LICENSE, THIRD_PARTY, CHANGELOG, CITATION, docs/)
#   P/share/man/man1/gridfree{,-worker}.1   (generated, cmake/CliDocs.cmake)
#   P/share/bash-completion/completions/gridfree{,-worker}
#   P/share/modulefiles/gridfree/<version>.lua  (Lmod; finds P from its own path)
include(GNUInstallDirs)
# Libraries found outside the system's directories (a user prefix, Spack, a
# module) are recorded in the installed executables' RPATH, so the worker
# still finds them where their module is not loaded, as in a Slurm job.
# System libraries (the Debian package's) add nothing. A target property:
# the executables exist already; -DCMAKE_INSTALL_RPATH_USE_LINK_PATH=OFF
# keeps the CMake default.
if(NOT DEFINED CMAKE_INSTALL_RPATH_USE_LINK_PATH OR CMAKE_INSTALL_RPATH_USE_LINK_PATH)
  set_target_properties(gridfree gridfree-worker PROPERTIES INSTALL_RPATH_USE_LINK_PATH ON)
endif()

install(TARGETS gridfree gridfree-worker RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Study files resolve their relative paths (templates, particle files)
# against the study file's own folder, so they run from any directory.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/studies/ DESTINATION ${CMAKE_INSTALL_DATADIR}/gridfree/studies)
install(FILES ${CMAKE_SOURCE_DIR}/README.md ${CMAKE_SOURCE_DIR}/LICENSE ${CMAKE_SOURCE_DIR}/THIRD_PARTY.md
              ${CMAKE_SOURCE_DIR}/CHANGELOG.md ${CMAKE_SOURCE_DIR}/CITATION.cff
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
install(DIRECTORY ${GRIDFREE_CLI_DOCS_DIR}/man/ DESTINATION ${CMAKE_INSTALL_MANDIR})
install(DIRECTORY ${GRIDFREE_CLI_DOCS_DIR}/bash-completion/ DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion)

# The Lmod module file: the version from project(), the prefix found at load
# time from the file's own path (so the same file is right under
# `cmake --install --prefix`, DESTDIR staging and the Debian package).
configure_file(${CMAKE_SOURCE_DIR}/cmake/modulefile.lua.in
               ${CMAKE_BINARY_DIR}/share/modulefiles/gridfree/${PROJECT_VERSION}.lua @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/share/modulefiles/gridfree/${PROJECT_VERSION}.lua
        DESTINATION ${CMAKE_INSTALL_DATADIR}/modulefiles/gridfree)
