# BDDC on the Jacobian's MATIS (-interface_matis, docs/solver.md "BDDC"): one subdomain per rank,
# each the sum of the rank's own patches, seams and joints. PCBDDC (GMRES, right preconditioned, to
# 1e-10) must give the joints.csv of the direct solve of the whole model on 1 rank (forces to 1e-8
# of the largest, states identical), and lap-rows' load shares must keep the closed form's
# properties that check_lap_rows.py holds exactly (the symmetry of each lap, the end rows carrying
# most). -ksp_view shows that BDDC, not LU, preconditioned the solves. On these models every dof
# that two subdomains share is a primal one (interface = coarse in -ksp_view's statistics: the
# shared dof are joint nodes and short seams), so BDDC is exact and each GMRES solve converges in
# one iteration but for round-off: more than 3 means the MATIS is not J (a joint block left out of
# it gives 400 iterations and no convergence).
function(boltnet_run_bddc name ranks scene)
  set(out ${BOLTNET_OUT}/${name}_bddc_np${ranks})
  add_test(NAME run_${name}_bddc_np${ranks}
    COMMAND ${BOLTNET_EXPECT} --match "steps converged" --match "There are no unused options" --match "type: bddc" --reject "^  type: lu\$"
            --reject "Linear solve did not converge" --reject "CONVERGED_RTOL iterations ([4-9]|[0-9][0-9]+)\$" --
            ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${scene}
            -output_dir ${out} -options_left -malloc_debug -malloc_dump -interface_matis -ksp_view ::ascii_info -ksp_converged_reason ${ARGN})
  set_tests_properties(run_${name}_bddc_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}"
    FIXTURES_SETUP ${name}_bddc_np${ranks} FAIL_REGULAR_EXPRESSION "PETSC ERROR;bytes [A-Za-z_0-9]+\\(\\) at ")
endfunction()

foreach(ranks 1 2 3)
  boltnet_run_bddc(lap_rows ${ranks} ${BOLTNET_SCENES}/lap-rows.yaml)
  add_test(NAME lap_rows_bddc_np${ranks}_vs_whole
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/lap_rows_whole_np1/joints.csv ${BOLTNET_OUT}/lap_rows_bddc_np${ranks}/joints.csv 1e-8)
  set_tests_properties(lap_rows_bddc_np${ranks}_vs_whole PROPERTIES FIXTURES_REQUIRED "lap_rows_whole_np1;lap_rows_bddc_np${ranks}")
  add_test(NAME lap_rows_bddc_np${ranks}_closed_form
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_lap_rows.py ${BOLTNET_OUT}/lap_rows_bddc_np${ranks}/joints.csv 21820 72000 20 1.27 20)
  set_tests_properties(lap_rows_bddc_np${ranks}_closed_form PROPERTIES FIXTURES_REQUIRED lap_rows_bddc_np${ranks})
endforeach()
# summary.json names the solve, and its GMRES iterations are at most 3 per linear solve.
add_test(NAME lap_rows_bddc_np2_summary
  COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['interface_solve'], s['krylov_iterations'], 'GMRES iterations in', s['linear_solves'], 'solves'); sys.exit(0 if s['interface_solve'] == 'bddc' and 0 < s['krylov_iterations'] <= 3 * s['linear_solves'] else 1)"
          ${BOLTNET_OUT}/lap_rows_bddc_np2/summary.json)
set_tests_properties(lap_rows_bddc_np2_summary PROPERTIES FIXTURES_REQUIRED lap_rows_bddc_np2)
# Frictional: the small plate grid (14 fasteners through stick, slide and bearing), condensed and
# kept whole, on 2 and 3 ranks (cut into patches joined by seams across the ranks).
foreach(ranks 2 3)
  foreach(variant condensed whole)
    set(_name plate_grid_small_${variant})
    set(_args)
    if(variant STREQUAL "whole")
      set(_args -patch_condense false)
    endif()
    boltnet_run_bddc(${_name} ${ranks} ${BOLTNET_OUT}/grid/small.yaml ${_args})
    set_tests_properties(run_${_name}_bddc_np${ranks} PROPERTIES FIXTURES_REQUIRED grid_scene)
    add_test(NAME ${_name}_bddc_np${ranks}_vs_whole
      COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/plate_grid_small_whole_np1/joints.csv ${BOLTNET_OUT}/${_name}_bddc_np${ranks}/joints.csv 1e-8)
    set_tests_properties(${_name}_bddc_np${ranks}_vs_whole PROPERTIES FIXTURES_REQUIRED "plate_grid_small_whole_np1;${_name}_bddc_np${ranks}")
  endforeach()
endforeach()
# Patches cut across the ranks (seams between subdomains), with MUMPS as BDDC's subdomain solvers:
# J is not symmetric, and BDDC's primal basis functions computed as for a symmetric matrix (its
# default, which boltnet turns off) leave GMRES at 400 iterations near the initial residual here.
foreach(ranks 2 3)
  boltnet_run_bddc(plate_grid_small_cut ${ranks} ${BOLTNET_OUT}/grid/small.yaml -patch_condense false -patch_max_nodes 200
    -pc_bddc_dirichlet_pc_factor_mat_solver_type mumps -pc_bddc_neumann_pc_factor_mat_solver_type mumps)
  set_tests_properties(run_plate_grid_small_cut_bddc_np${ranks} PROPERTIES FIXTURES_REQUIRED grid_scene)
  add_test(NAME plate_grid_small_cut_bddc_np${ranks}_vs_whole
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/plate_grid_small_whole_np1/joints.csv ${BOLTNET_OUT}/plate_grid_small_cut_bddc_np${ranks}/joints.csv 1e-8)
  set_tests_properties(plate_grid_small_cut_bddc_np${ranks}_vs_whole PROPERTIES FIXTURES_REQUIRED "plate_grid_small_whole_np1;plate_grid_small_cut_bddc_np${ranks}")
endforeach()
# Load cases on one set-up (each case starts from a fresh BDDC, AssemblyResetPC): the strip's
# tension, bending and bending-back cases on 2 ranks against the exact constant-strain and
# constant-curvature solutions, as test/cases_tests.cmake checks the direct solve's.
boltnet_run_bddc(strip_cases 2 ${BOLTNET_TEST_SCENES}/strip-cases.yaml)
foreach(case_load "tension;tension" "bending;bending" "bending-back;bending")
  list(GET case_load 0 case)
  list(GET case_load 1 load)
  add_test(NAME strip_cases_bddc_${case}_exact_np2
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_strip.py ${BOLTNET_OUT}/strip_cases_bddc_np2/${case} ${load} 72000 20 1.27 1e-8)
  set_tests_properties(strip_cases_bddc_${case}_exact_np2 PROPERTIES FIXTURES_REQUIRED strip_cases_bddc_np2)
endforeach()
# A linear solve that fails (one GMRES iteration allowed, to 1e-14) is cut back with a fresh BDDC
# (a PCSetUp after PCReset crashes in PETSc 3.18.5's PCBDDCGraphInit), and the run says where it
# stopped.
boltnet_expect(bddc_cutback_fails_cleanly 3 --fail --match "FAILED: Load step 1 from load factor 0 to 400 did not converge .* after 2 cut-backs"
  --reject "SEGV|PETSC ERROR"
  -- ${BOLTNET_MPIRUN} 3 --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_OUT}/grid/small.yaml
  -output_dir ${BOLTNET_OUT}/bddc_cutback -output_fields false -patch_condense false -patch_max_nodes 200 -interface_matis
  -ksp_max_it 1 -ksp_rtol 1e-14 -load_max_cuts 2)
set_tests_properties(bddc_cutback_fails_cleanly_np3 PROPERTIES FIXTURES_REQUIRED grid_scene)
# The lagged solve keeps a factorisation, which BDDC does not have: refused, with one line.
boltnet_expect(bddc_lagged_refused 1 --fail --max-lines 1 --match "interface_solve lagged keeps a factorisation of J. with -interface_matis"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${BOLTNET_OUT}/bddc_lagged_refused -interface_matis -interface_solve lagged)
