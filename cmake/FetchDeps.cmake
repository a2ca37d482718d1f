# SPDX-License-Identifier: GPL-3.0-or-later
# -DGRIDFREE_FETCH_DEPS=ON: the header-only dependencies that CMake cannot
# find (Eigen, nlohmann/json, CLI11) are downloaded at configure time, at the
# versions Debian 12 ships (the ones built and tested), each checked against
# its SHA-256. Off by default: nothing is downloaded unless asked, and a
# dependency found on the system (CMAKE_PREFIX_PATH, a module, Spack) is
# always preferred. SQLite, spdlog and FFTW3 are compiled libraries and are
# never fetched (docs/INSTALL.md "Without root").
option(GRIDFREE_FETCH_DEPS "Download Eigen, nlohmann/json and CLI11 (pinned, hashed) when not found" OFF)
if(NOT GRIDFREE_FETCH_DEPS)
  return()
endif()
include(FetchContent)

# gridfree_fetch_headers(NAME URL SHA256 TARGET INCLUDE_SUBDIR): an
# INTERFACE imported TARGET over the archive's INCLUDE_SUBDIR.
function(gridfree_fetch_headers name url sha256 target include_subdir)
  FetchContent_Declare(${name} URL ${url} URL_HASH SHA256=${sha256} DOWNLOAD_EXTRACT_TIMESTAMP TRUE)
  FetchContent_GetProperties(${name})
  if(NOT ${name}_POPULATED)
    # Only the sources: the projects' own CMakeLists (tests, docs) are not run.
    FetchContent_Populate(${name})
  endif()
  add_library(${target} INTERFACE IMPORTED GLOBAL)
  target_include_directories(${target} SYSTEM INTERFACE ${${name}_SOURCE_DIR}/${include_subdir})
  message(STATUS "gridfree: ${target} from ${${name}_SOURCE_DIR} (${url})")
endfunction()

find_package(Eigen3 3.4 QUIET NO_MODULE)
if(NOT TARGET Eigen3::Eigen)
  gridfree_fetch_headers(gridfree_eigen
    https://gitlab.com/libeigen/eigen/-/archive/3.4.0/eigen-3.4.0.tar.gz
    8586084f71f9bde545ee7fa6d00288b264a2b7ac3607b974e54d13e7162c1c72
    Eigen3::Eigen .)
endif()
find_package(nlohmann_json 3.10 QUIET)
if(NOT TARGET nlohmann_json::nlohmann_json)
  gridfree_fetch_headers(gridfree_nlohmann_json
    https://github.com/nlohmann/json/archive/v3.11.2.tar.gz
    d69f9deb6a75e2580465c6c4c5111b89c4dc2fa94e3a85fcd2ffcd9a143d9273
    nlohmann_json::nlohmann_json include)
endif()
find_package(CLI11 QUIET)
if(NOT TARGET CLI11::CLI11)
  gridfree_fetch_headers(gridfree_cli11
    https://github.com/CLIUtils/CLI11/archive/v2.1.2.tar.gz
    26291377e892ba0e5b4972cdfd4a2ab3bf53af8dac1f4ea8fe0d1376b625c8cb
    CLI11::CLI11 include)
endif()
