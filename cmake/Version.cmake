# SPDX-License-Identifier: GPL-3.0-or-later
# The version comes from one place, project(... VERSION) in CMakeLists.txt;
# the binaries record it with the source revision (short git sha, "unknown"
# outside git) and the build type, which `--version` prints.
execute_process(
  COMMAND git rev-parse --short=10 HEAD
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
  OUTPUT_VARIABLE GRIDFREE_GIT_SHA
  OUTPUT_STRIP_TRAILING_WHITESPACE
  ERROR_QUIET)
if(NOT GRIDFREE_GIT_SHA)
  set(GRIDFREE_GIT_SHA "unknown")
endif()
if(CMAKE_BUILD_TYPE)
  set(GRIDFREE_BUILD_TYPE "${CMAKE_BUILD_TYPE}")
else()
  set(GRIDFREE_BUILD_TYPE "unknown")
endif()
configure_file(${CMAKE_SOURCE_DIR}/cmake/version_info.cpp.in
               ${CMAKE_BINARY_DIR}/generated/version_info.cpp @ONLY)
