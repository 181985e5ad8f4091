# Linear where it can be (docs/solver.md): with -joint_stuck_linear (the default)
# joints that stay stuck are solved as linear springs, every one is checked with the full law before
# a step is accepted, and the Jacobian and its factorisation are kept while no joint's tangent
# changes. The reference is the same run with the option off (the full law everywhere, a new
# Jacobian per Newton iteration): the results must not change.
#   - Where the frozen joints do not change the Newton iterates (a joint solved as a spring follows
#     the same affine law the full law gives it in stick), the results are the same to round-off:
#     fig3c, double-lap, fig3b, the small plate grid (1e-10 of each quantity's scale).
#   - On chain (2D frictional network) some steps take other Newton paths (a joint the full law
#     would have sent into slide for one iterate stays a spring) and the converged points differ
#     within the solver's tolerance: 1.4e-9 of the scale measured (1e-12 with -snes_atol 1e-13), so
#     1e-8, as for other comparisons of different solution paths (hard_chain_one_step_same_solution).
foreach(case fig3c chain)
  if(case STREQUAL "fig3c")
    set(_scene ${BOLTNET_SCENES}/fig3c.yaml)
    set(_tol 1e-10)
  else()
    set(_scene ${BOLTNET_TEST_SCENES}/chain.yaml)
    set(_tol 1e-8)
  endif()
  boltnet_run(${case}_full_law 1 ${_scene} -joint_stuck_linear false)
  add_test(NAME stuck_linear_same_results_${case}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/${case}_full_law_np1/joints.csv ${BOLTNET_OUT}/${case}_np1/joints.csv ${_tol})
  set_tests_properties(stuck_linear_same_results_${case} PROPERTIES FIXTURES_REQUIRED "${case}_np1;${case}_full_law_np1")
endforeach()
foreach(ranks 1 2)
  boltnet_run(double_lap_full_law ${ranks} ${BOLTNET_SCENES}/double-lap.yaml -joint_stuck_linear false)
  add_test(NAME stuck_linear_same_results_double_lap_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/double_lap_full_law_np${ranks}/joints.csv ${BOLTNET_OUT}/double_lap_np${ranks}/joints.csv 1e-10)
  set_tests_properties(stuck_linear_same_results_double_lap_np${ranks} PROPERTIES FIXTURES_REQUIRED "double_lap_np${ranks};double_lap_full_law_np${ranks}")
endforeach()
boltnet_run(fig3b_full_law 1 ${BOLTNET_SCENES}/fig3b.yaml -load_steps 30 -joint_stuck_linear false)
add_test(NAME stuck_linear_same_results_fig3b
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/fig3b_full_law_np1/joints.csv ${BOLTNET_OUT}/fig3b_np1/joints.csv 1e-10)
set_tests_properties(stuck_linear_same_results_fig3b PROPERTIES FIXTURES_REQUIRED "fig3b_np1;fig3b_full_law_np1")
foreach(ranks 1 3)
  boltnet_run(plate_grid_small_full_law ${ranks} ${BOLTNET_OUT}/grid/small.yaml -joint_stuck_linear false)
  set_tests_properties(run_plate_grid_small_full_law_np${ranks} PROPERTIES FIXTURES_REQUIRED grid_scene)
  add_test(NAME stuck_linear_same_results_plate_grid_small_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/plate_grid_small_full_law_np${ranks}/joints.csv ${BOLTNET_OUT}/plate_grid_small_np${ranks}/joints.csv 1e-10)
  set_tests_properties(stuck_linear_same_results_plate_grid_small_np${ranks} PROPERTIES FIXTURES_REQUIRED "plate_grid_small_np${ranks};plate_grid_small_full_law_np${ranks}")
endforeach()

# Joints solved as springs that the full law sends out of stick are released and the step solves on:
# on chain with -joint_stuck_margin 0.8 (more joints frozen than by default), as load shares shift,
# joints predicted to stay stuck slide (released >= 1); the results are the full law's (1e-8, as above).
boltnet_run(chain_margin08 1 ${BOLTNET_TEST_SCENES}/chain.yaml -joint_stuck_margin 0.8)
add_test(NAME stuck_linear_released_chain
  COMMAND grep -Eq "\"released\": [1-9]" ${BOLTNET_OUT}/chain_margin08_np1/summary.json)
set_tests_properties(stuck_linear_released_chain PROPERTIES FIXTURES_REQUIRED chain_margin08_np1)
add_test(NAME stuck_linear_same_results_chain_margin08
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/chain_full_law_np1/joints.csv ${BOLTNET_OUT}/chain_margin08_np1/joints.csv 1e-8)
set_tests_properties(stuck_linear_same_results_chain_margin08 PROPERTIES FIXTURES_REQUIRED "chain_margin08_np1;chain_full_law_np1")

# Every joint a linear spring (fig3b's bolts as springs of their bearing stiffness), 10 steps: one
# Jacobian and one factorisation for the whole run, on 1, 2 and 3 ranks, the same results as a
# factorisation per step (1e-12 of the scale).
set(_springs)
foreach(t c02 c05 c08 c11)
  list(APPEND _springs -joint_${t}_law spring -joint_${t}_kt 4e4)
endforeach()
foreach(ranks 1 2 3)
  boltnet_run(fig3b_springs ${ranks} ${BOLTNET_SCENES}/fig3b.yaml -load_steps 10 ${_springs})
endforeach()
boltnet_run(fig3b_springs_full_law 2 ${BOLTNET_SCENES}/fig3b.yaml -load_steps 10 ${_springs} -joint_stuck_linear false)
foreach(ranks 1 2 3)
  add_test(NAME stuck_linear_one_factorisation_np${ranks}
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; a=json.load(open(sys.argv[1])); b=json.load(open(sys.argv[2])); sys.exit(not (a['jacobians_assembled'] == 1 and a['jacobians_reused'] == 9 and b['jacobians_assembled'] == 10))"
            ${BOLTNET_OUT}/fig3b_springs_np${ranks}/summary.json ${BOLTNET_OUT}/fig3b_springs_full_law_np2/summary.json)
  set_tests_properties(stuck_linear_one_factorisation_np${ranks} PROPERTIES FIXTURES_REQUIRED "fig3b_springs_np${ranks};fig3b_springs_full_law_np2")
  add_test(NAME stuck_linear_same_results_springs_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/fig3b_springs_full_law_np2/joints.csv ${BOLTNET_OUT}/fig3b_springs_np${ranks}/joints.csv 1e-12)
  set_tests_properties(stuck_linear_same_results_springs_np${ranks} PROPERTIES FIXTURES_REQUIRED "fig3b_springs_np${ranks};fig3b_springs_full_law_np2")
endforeach()

# A margin outside [0, 1] is refused, naming the option.
boltnet_expect(bad_stuck_margin 1 ${_bad} --match "-joint_stuck_margin 1.5 must lie in \\[0, 1\\]"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -joint_stuck_margin 1.5)

# scripts/bench-plate-grid --stuck-linear on its tiny grid: both runs converge and it writes its table
# (the measured ratios are in docs/performance.md; no timing is checked).
add_test(NAME bench_plate_grid_stuck_linear_tiny
  COMMAND ${BOLTNET_EXPECT} --match "^\\| 1 \\| true \\(default\\) \\| converged" --match "^\\| 1 \\| false \\| converged"
          --match "wrote ${BOLTNET_OUT}/bench-stuck-tiny.md"
          -- ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/bench-plate-grid --size tiny --ranks 1 --stuck-linear
          --boltnet $<TARGET_FILE:boltnet_driver> --mpiexec ${MPIEXEC_EXECUTABLE} --out ${BOLTNET_OUT}/bench-stuck-tiny.md)
set_tests_properties(bench_plate_grid_stuck_linear_tiny PROPERTIES ENVIRONMENT "${BOLTNET_ENV}")

# -info counts, for each Jacobian, the joints whose tangent differs from the last Jacobian's, summed
# over the ranks. References: a linear spring's tangent is its constant stiffness, so lap-rows' 10
# springs give "0 of the 10" on every rank count (the total, not a rank's share); fig3c's one bolt
# slides and bears, where its tangent follows the jump (docs/joint-laws.md), so "1 of the 1" appears.
foreach(ranks 1 2 3)
  set(info ${BOLTNET_OUT}/jacobian_tangent_count_springs_np${ranks}.info)
  boltnet_expect(jacobian_tangent_count_springs ${ranks} --match "0 of the 10 joints' tangents differ from the last Jacobian's"
    --reject "[1-9][0-9]* of the 10 joints' tangents" --info ${info} --
    ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml
    -output_dir ${BOLTNET_OUT}/jacobian_tangent_count_springs_np${ranks} -output_fields false -load_steps 3 -info ${info})
endforeach()
boltnet_expect(jacobian_tangent_count_bolt 1 --match "1 of the 1 joints' tangents differ from the last Jacobian's"
  --match "0 of the 1 joints' tangents differ from the last Jacobian's" --
  $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/jacobian_tangent_count_bolt
  -output_fields false -info)

# The SNES type may be changed on the command line: -snes_type ksponly (one linear solve, no line
# search of boltnet's) gives the SNES a new line search: the set-up must not reach the one it
# destroyed (solver/stepper.cpp; scripts/sanitize runs this under ASan). lap-rows' springs are linear,
# so the one solve is the solution: it must balance its loads like a Newton step (the load path's
# equilibrium check), on 1, 2 and 3 ranks. And scripts/bench-plate-grid --solvers, whose runs are all
# -snes_type ksponly, on its tiny grid: MUMPS condensed and kept whole both converge.
foreach(ranks 1 2 3)
  boltnet_expect(snes_ksponly_springs ${ranks} --match "^boltnet: 1 steps converged"
    -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml
    -output_dir ${BOLTNET_OUT}/snes_ksponly_springs_np${ranks} -output_fields false -load_steps 1
    -load_max_cuts 0 -snes_type ksponly)
endforeach()
add_test(NAME bench_plate_grid_solvers_tiny
  COMMAND ${BOLTNET_EXPECT} --match "^\\| 1 \\| MUMPS LU \\(default, condensed\\) \\| [^|]+ \\| converged"
          --match "^\\| 1 \\| MUMPS LU, kept whole \\| [^|]+ \\| converged"
          --match "^\\| 1 \\| GMRES \\+ BDDC, condensed \\| [^|]+ \\| converged" --match "^\\| 1 \\| GMRES \\+ BDDC, kept whole \\| [^|]+ \\| converged"
          --match "^\\| 1 \\| GMRES \\+ GAMG on the slave split \\| `-options_file share/solvers/multigrid.opts[^|]*` \\| converged" --match "wrote ${BOLTNET_OUT}/bench-solvers-tiny.md"
          -- ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/bench-plate-grid --size tiny --ranks 1 --solvers --timeout 30
          --boltnet $<TARGET_FILE:boltnet_driver> --mpiexec ${MPIEXEC_EXECUTABLE} --out ${BOLTNET_OUT}/bench-solvers-tiny.md)
set_tests_properties(bench_plate_grid_solvers_tiny PROPERTIES ENVIRONMENT "${BOLTNET_ENV}")
# --rows: the references (rows 0 and 1) and the rows asked for, no others.
add_test(NAME bench_plate_grid_solvers_rows_tiny
  COMMAND ${BOLTNET_EXPECT} --match "^\\| 1 \\| MUMPS LU \\(default, condensed\\) \\|" --match "^\\| 1 \\| MUMPS LU, kept whole \\|"
          --match "^\\| 1 \\| GMRES \\+ GAMG on the slave split \\| [^|]+ \\| converged" --reject "BDDC" --reject "BoomerAMG"
          -- ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/bench-plate-grid --size tiny --ranks 1 --solvers --rows 6 --timeout 30
          --boltnet $<TARGET_FILE:boltnet_driver> --mpiexec ${MPIEXEC_EXECUTABLE})
set_tests_properties(bench_plate_grid_solvers_rows_tiny PROPERTIES ENVIRONMENT "${BOLTNET_ENV}")
