# SPDX-License-Identifier: GPL-3.0-or-later
# Man pages and bash completion, written at build time by the executables
# themselves from their CLI11 definitions (`PROGRAM --man-page`,
# `PROGRAM --bash-completion`; worker/src/clidoc/), so no option is written
# twice. Outputs go to build/share/, in the layout they are installed in.
set(GRIDFREE_CLI_DOCS_DIR ${CMAKE_BINARY_DIR}/share)
set(GRIDFREE_CLI_DOCS "")
foreach(program gridfree gridfree-worker)
  set(man ${GRIDFREE_CLI_DOCS_DIR}/man/man1/${program}.1)
  set(completion ${GRIDFREE_CLI_DOCS_DIR}/bash-completion/completions/${program})
  add_custom_command(
    OUTPUT ${man} ${completion}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${GRIDFREE_CLI_DOCS_DIR}/man/man1
            ${GRIDFREE_CLI_DOCS_DIR}/bash-completion/completions
    COMMAND sh -c "\"$1\" --man-page > \"$2.tmp\" && mv \"$2.tmp\" \"$2\" && \"$1\" --bash-completion > \"$3.tmp\" && mv \"$3.tmp\" \"$3\""
            sh $<TARGET_FILE:${program}> ${man} ${completion}
    DEPENDS ${program}
    COMMENT "Man page and bash completion of ${program}"
    VERBATIM)
  list(APPEND GRIDFREE_CLI_DOCS ${man} ${completion})
endforeach()
add_custom_target(cli_docs ALL DEPENDS ${GRIDFREE_CLI_DOCS})
