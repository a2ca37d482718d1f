# SPDX-License-Identifier: GPL-3.0-or-later
# Embeds schemas/*.schema.json into the binaries, so the installed tools need no source tree.
file(GLOB GRIDFREE_SCHEMA_FILES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/schemas/*.schema.json)
set(GRIDFREE_SCHEMA_ENTRIES "")
foreach(schema_file IN LISTS GRIDFREE_SCHEMA_FILES)
  get_filename_component(schema_name ${schema_file} NAME)
  string(REGEX REPLACE "\\.json$" "" schema_name "${schema_name}")
  file(READ ${schema_file} schema_text)
  string(APPEND GRIDFREE_SCHEMA_ENTRIES "    {\"${schema_name}\", R\"gridfree_schema(${schema_text})gridfree_schema\"},\n")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${schema_file})
endforeach()
configure_file(${CMAKE_SOURCE_DIR}/cmake/embedded_schemas.cpp.in
               ${CMAKE_BINARY_DIR}/generated/embedded_schemas.cpp @ONLY)
