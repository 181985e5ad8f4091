# The documentation cannot drift from the code: options tables and defaults against -help, links
# against the files, and the foreign-program study against the program. Included from
# test/CMakeLists.txt (BOLTNET_PYTHON).

# Requirement: every options table between options-doc markers in README.md and docs/*.md is what
# the programs' -help prints (names, defaults, help text), and every default named in the prose
# ("`-x` (default 3)") is -help's. Reference: the programs themselves.
add_test(NAME options_doc
  COMMAND ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/options-doc --check --build ${PROJECT_BINARY_DIR})
# ... and the check fails on the drift it is there for: scenes.md once gave the watchdog's default
# as 5 (a table) and a prose default can be wrong the same way.
add_test(NAME options_doc_catches_drift
  COMMAND sh -c "t=$(mktemp -d) && trap 'rm -rf $t' EXIT && sed 's/^| `-snes_linesearch_boltnet_watchdog` | 3 |/| `-snes_linesearch_boltnet_watchdog` | 5 |/' \"$1/docs/scenes.md\" >$t/scenes.md && printf 'The watchdog (`-snes_linesearch_boltnet_watchdog`, default 5).\\n' >$t/prose.md && \"$0\" \"$1/scripts/options-doc\" --check --build \"$2\" $t/scenes.md $t/prose.md; echo \"[exit status $?]\""
          ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR} ${PROJECT_BINARY_DIR})
set_tests_properties(options_doc_catches_drift PROPERTIES PASS_REGULAR_EXPRESSION
  "-\\| `-snes_linesearch_boltnet_watchdog` \\| 5 \\|.*\\+\\| `-snes_linesearch_boltnet_watchdog` \\| 3 \\|.*prose.md:1: `-snes_linesearch_boltnet_watchdog` default 5, but -help says 3.*\\[exit status 1\\]")

# Requirement: every relative link (and every page named in the text) of README.md and docs/*.md
# leads to a file of the repository. Reference: the file system.
add_test(NAME doc_links COMMAND ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/check-doc-links)
# ... and it fails on a broken link and on a page named in the text that does not exist.
add_test(NAME doc_links_catch_broken
  COMMAND sh -c "t=$(mktemp -d) && trap 'rm -rf $t' EXIT && : >$t/solver.md && printf 'See [the solver](solver.md), [nothing](no-such-page.md#x) and benchmarks.md.\\n' >$t/page.md && \"$0\" \"$1/scripts/check-doc-links\" $t/page.md; echo \"[exit status $?]\""
          ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR})
set_tests_properties(doc_links_catch_broken PROPERTIES PASS_REGULAR_EXPRESSION
  "link to no-such-page.md#x: no such file.*names the page benchmarks.md, which is not in the repository.*\\[exit status 1\\]"
  FAIL_REGULAR_EXPRESSION "link to solver.md")

# Requirement: the table of docs/petsc-plugin.md is what test/foreign_switch gives with each line
# search (so the doc cannot drift from the line search), with the same numbers on 1 and 2 ranks
# (the results do not depend on the ranks), and boltnet's two state interfaces (a count,
# switch indicators) give identical runs. Reference: the program, and the other rank count.
foreach(ranks 1 2)
  add_test(NAME foreign_switch_study_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/study-foreign-switch --check --ranks ${ranks} --build ${PROJECT_BINARY_DIR})
  set_tests_properties(foreign_switch_study_np${ranks} PROPERTIES PROCESSORS ${ranks} TIMEOUT 1200
    ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_btl_vader_single_copy_mechanism=none")
endforeach()
