# Tests of boltnet as seen from outside: the line search plugin in a PETSc program that does not link
# boltnet, the public C API (boltnet.h) against closed forms, and the installed package.
# Included from test/CMakeLists.txt, which defines boltnet_mpi_test().
#
# The MPI runs use -options_left (a left option fails the test: Debian's PETSc ignores typos) and
# -malloc_debug -malloc_dump (Debian's build is not a debug build, but -malloc_debug turns PETSc's
# tracing malloc on, and -malloc_dump then lists every PETSc allocation not freed: the test fails).
set(BOLTNET_TEST_FAIL_REGEX "PETSC ERROR;unused database option;bytes [A-Za-z_0-9]+\\(\\) at ")

# boltnet_checked_mpi_test(NAME RANKS REGEX COMMAND...): like boltnet_mpi_test, for tests that check
# the output with PASS_REGULAR_EXPRESSION. ctest ignores the exit code of such tests, so the command
# runs under `sh -c` which appends "[exit status N]" (mpiexec's status: non-zero when any rank
# failed) and REGEX has to match that too. The environment is boltnet_mpi_test's.
function(boltnet_checked_mpi_test name ranks regex)
  add_test(NAME ${name}_np${ranks}
    COMMAND sh -c "\"$@\" 2>&1; echo \"[exit status $?]\"" sh
            ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${ranks} --oversubscribe ${ARGN})
  set_tests_properties(${name}_np${ranks} PROPERTIES PROCESSORS ${ranks}
    PASS_REGULAR_EXPRESSION "${regex}"
    ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_btl_vader_single_copy_mechanism=none")
endfunction()

# ---------------------------------------------------------------------------------------------------
# foreign_snes: PETSc and MPI only. Requirement: any PETSc program gets the boltnet line search with
# -dll_append libboltnet_snes.so, and without it the type is unknown.
add_executable(foreign_snes foreign_snes.c)
target_link_libraries(foreign_snes PRIVATE PkgConfig::PETSC MPI::MPI_C m)

# The program must not depend on libboltnet, directly or through another library.
add_test(NAME foreign_snes_no_boltnet_dependency
  COMMAND sh -c "deps=$(ldd \"$0\") || exit 1; if echo \"$deps\" | grep boltnet; then echo \"$0 depends on libboltnet\"; exit 1; fi; echo \"$0: no libboltnet among its $(echo \"$deps\" | wc -l) shared libraries\""
          $<TARGET_FILE:foreign_snes>)

# With the plugin: converges to the exact solution with the boltnet line search, which had to cut
# steps (quadratic backtracks >= 1, as the full steps diverge: see foreign_snes_full_newton_fails),
# shown by -snes_view; no option left unused. (PETSc 3.18 has no -snes_linesearch_view: the line
# search is viewed inside -snes_view.)
set(_foreign_ok
  "type: boltnet\n *boltnet: alpha [^\n]*not attached[^\n]*\n *boltnet: watchdog full steps 0, half steps 0, steps limited to a state change 0, plateau steps lengthened 0, quadratic backtracks [1-9][0-9]*\n.*line search type boltnet\n.*foreign_snes: PASS\n.*There are no unused options.*\\[exit status 0\\]")
foreach(ranks 1 2)
  boltnet_checked_mpi_test(foreign_snes_plugin ${ranks} "${_foreign_ok}"
    $<TARGET_FILE:foreign_snes> -dll_append $<TARGET_FILE:boltnet_snes>
    -snes_linesearch_type boltnet -snes_view -options_left -malloc_debug -malloc_dump)
  set_tests_properties(foreign_snes_plugin_np${ranks} PROPERTIES FAIL_REGULAR_EXPRESSION "${BOLTNET_TEST_FAIL_REGEX}")
endforeach()

# Without the plugin, the type is unknown: a PETSc error naming it and a non-zero exit code.
boltnet_checked_mpi_test(foreign_snes_without_plugin 1
  "Unable to find requested Line Search type boltnet\n.*\\[exit status [1-9][0-9]*\\]"
  $<TARGET_FILE:foreign_snes> -snes_linesearch_type boltnet)

# The problem is a real test of a line search: full Newton steps (basic) do not converge from x0.
# PETSc's error message goes to stderr and may land between the program's own lines.
boltnet_checked_mpi_test(foreign_snes_full_newton_fails 1
  "line search type basic\n.*foreign_snes: SNES DIVERGED_.*\\[exit status [1-9][0-9]*\\]"
  $<TARGET_FILE:foreign_snes> -snes_linesearch_type basic)

# ---------------------------------------------------------------------------------------------------
# foreign_switch: PETSc and MPI only, a problem with a switching (piecewise-linear) residual.
# Requirement: a PETSc program that loads the plugin gives the boltnet line search its states without
# linking boltnet, by composing on its SNES a state-change count or switch indicators
# (docs/petsc-plugin.md), and the line search then converges where full Newton steps chatter.
add_executable(foreign_switch foreign_switch.c)
target_link_libraries(foreign_switch PRIVATE PkgConfig::PETSC MPI::MPI_C m)
add_test(NAME foreign_switch_no_boltnet_dependency
  COMMAND sh -c "deps=$(ldd \"$0\") || exit 1; if echo \"$deps\" | grep boltnet; then echo \"$0 depends on libboltnet\"; exit 1; fi; echo \"$0: no libboltnet among its $(echo \"$deps\" | wc -l) shared libraries\""
          $<TARGET_FILE:foreign_switch>)

# The problem needs a line search: full Newton steps chatter between states to the iteration limit
# (blocks still change state in the last 10 iterations), and the program says so with a non-zero exit.
# PETSc's error message goes to stderr and may land between the program's own lines.
boltnet_checked_mpi_test(foreign_switch_basic_chatters 1
  "line search type basic, state none\n.*foreign_switch: SNES DIVERGED_MAX_IT after 100 Newton iterations[^\n]*\n.*foreign_switch: blocks that changed state over the last 10 iterations: [1-9][0-9]*\n.*\\[exit status [1-9][0-9]*\\]"
  $<TARGET_FILE:foreign_switch> -snes_linesearch_type basic)

# With the plugin and each interface (switch indicators, a count composed on the SNES, the line
# search's setter found by name), at 1, 2 and 3 ranks: converged to u* (PASS), -snes_view
# says which state function the line search uses and that it used it: a step limited to a state
# change or a half step of the watchdog (neither is taken without states); no
# option unused, no PETSc allocation leaked (the composed Vec and the line search's work vectors).
set(_switch_view_switches "state function attached \\(switch indicators SNESLineSearchBoltnetSwitches_C composed on the SNES\\)")
set(_switch_view_count "state function attached \\(SNESLineSearchBoltnetStateChange_C composed on the SNES\\)")
set(_switch_view_setter "state function attached \\(SNESLineSearchBoltnetSetStateChangeFunction\\)")
foreach(state switches count setter)
  foreach(ranks 1 2 3)
    boltnet_checked_mpi_test(foreign_switch_boltnet_${state} ${ranks}
      "type: boltnet\n *boltnet: alpha [^\n]*${_switch_view_${state}}\n *boltnet: watchdog full steps [0-9]+, (half steps [1-9][0-9]*, steps limited to a state change [0-9]+|half steps [0-9]+, steps limited to a state change [1-9][0-9]*),[^\n]*\n.*line search type boltnet, state ${state}\n.*foreign_switch: PASS\n.*There are no unused options.*\\[exit status 0\\]"
      $<TARGET_FILE:foreign_switch> -dll_append $<TARGET_FILE:boltnet_snes> -snes_linesearch_type boltnet -state ${state}
      -snes_view -options_left -malloc_debug -malloc_dump)
    set_tests_properties(foreign_switch_boltnet_${state}_np${ranks} PROPERTIES FAIL_REGULAR_EXPRESSION "${BOLTNET_TEST_FAIL_REGEX}")
  endforeach()
endforeach()
# A switch function composed without the Vec of its layout: the line search says what is missing.
boltnet_checked_mpi_test(foreign_switch_switches_without_layout 2
  "A switch function is composed on the SNES as \"SNESLineSearchBoltnetSwitches_C\" but no Vec of the switches' layout as \"SNESLineSearchBoltnetSwitches\".*\\[exit status [1-9][0-9]*\\]"
  $<TARGET_FILE:foreign_switch> -dll_append $<TARGET_FILE:boltnet_snes> -snes_linesearch_type boltnet -state switches_no_layout)

# ---------------------------------------------------------------------------------------------------
# test_api: boltnet.h only. Requirement: the public API gives the closed-form joint responses
# (friction: stick, slide, bearing, elastic unloading over 2G, reverse slip; spring; contact law)
# at 1, 2 and 3 ranks.
add_executable(test_api test_api.c)
target_link_libraries(test_api PRIVATE boltnet m)
foreach(ranks 1 2 3)
  boltnet_mpi_test(test_api ${ranks} $<TARGET_FILE:test_api> -options_left -malloc_debug -malloc_dump)
  set_tests_properties(test_api_np${ranks} PROPERTIES FAIL_REGULAR_EXPRESSION "${BOLTNET_TEST_FAIL_REGEX}")
endforeach()
# The same closed forms with the consistent tangent, set through the assemblies' option prefixes
# (an ignored prefix would leave the options unused).
boltnet_mpi_test(test_api_consistent_tangent 2 $<TARGET_FILE:test_api>
  -fric_joint_tangent consistent -lin_joint_tangent consistent -options_left -malloc_debug -malloc_dump)
set_tests_properties(test_api_consistent_tangent_np2 PROPERTIES FAIL_REGULAR_EXPRESSION "${BOLTNET_TEST_FAIL_REGEX}")

# ---------------------------------------------------------------------------------------------------
# test_capi_errors: boltnet.h only. Requirement: every entry point of the C API refuses a NULL
# pointer, a negative count or an id or count out of range with a PETSc error naming the function
# and the argument, before it allocates; std::bad_alloc inside the library (a load path of 10^6
# factors under a lowered RLIMIT_AS) is PETSC_ERR_MEM naming the function, not std::terminate; and
# the assembly still solves to the closed form afterwards. At 1, 2 and 3 ranks, no PETSc allocation
# leaked (the work vector of the load path that ran out of memory included).
add_executable(test_capi_errors test_capi_errors.c)
target_link_libraries(test_capi_errors PRIVATE boltnet m)
foreach(ranks 1 2 3)
  boltnet_mpi_test(test_capi_errors ${ranks} $<TARGET_FILE:test_capi_errors> -options_left -malloc_debug -malloc_dump)
  set_tests_properties(test_capi_errors_np${ranks} PROPERTIES FAIL_REGULAR_EXPRESSION "${BOLTNET_TEST_FAIL_REGEX}")
endforeach()

# ---------------------------------------------------------------------------------------------------
# check_install: install into a temporary prefix, build test_api.c against the installed package
# through pkg-config and through find_package(boltnet), run both; the installed plugin and driver
# find the installed library, and foreign_snes uses the installed plugin.
add_test(NAME check_install
  COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/check_install.sh ${PROJECT_BINARY_DIR} ${CMAKE_CURRENT_SOURCE_DIR}/test_api.c
          ${CMAKE_COMMAND} ${MPIEXEC_EXECUTABLE} ${CMAKE_INSTALL_LIBDIR} ${CMAKE_C_COMPILER} $<TARGET_FILE:foreign_snes>)
set_tests_properties(check_install PROPERTIES TIMEOUT 600)
