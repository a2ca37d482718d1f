# SPDX-License-Identifier: GPL-3.0-or-later
# Records the source revision in the binaries (falls back to "unknown" outside git).
execute_process(
  COMMAND git rev-parse --short=10 HEAD
  WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
  OUTPUT_VARIABLE GRIDFREE_GIT_SHA
  OUTPUT_STRIP_TRAILING_WHITESPACE
  ERROR_QUIET)
if(NOT GRIDFREE_GIT_SHA)
  set(GRIDFREE_GIT_SHA "unknown")
endif()
configure_file(${CMAKE_SOURCE_DIR}/cmake/version_info.cpp.in
               ${CMAKE_BINARY_DIR}/generated/version_info.cpp @ONLY)
