# The interface: condensed patches against patches kept whole, and the lagged interface solve
# against the direct one (docs/solver.md, "Condensed patches", "The interface solve").
#
# Condensation changes how the model is solved, not the model: every shipped shell scene (the
# 217,212-dof plate-grid included, without its fields: about 40 s a run kept whole, 8 s condensed,
# on one core), and the small generated plate grid (scripts/make-plate-grid, the shape of
# share/scenes/plate-grid.yaml), gives the same joints.csv with -patch_condense false (forces to 1e-8 of the largest, the
# solver's tolerance; states identical: compare_csv.py compares them as words) on 1, 2, 3 and 4
# ranks: each condensed run and each uncondensed run is compared against the uncondensed 1-rank run.
# (fig3c has rigid patches only: nothing to condense.)
foreach(scene fig3a fig3b lap_rows double_lap plate_grid plate_grid_small)
  string(REPLACE "_" "-" file ${scene})
  set(_scene ${BOLTNET_SCENES}/${file}.yaml)
  set(_args)
  set(_fixture)
  if(scene STREQUAL "fig3b")
    set(_args -load_steps 30) # as its default runs (test/CMakeLists.txt)
  elseif(scene STREQUAL "plate_grid")
    set(_args -output_fields false)
  elseif(scene STREQUAL "plate_grid_small")
    set(_scene ${BOLTNET_OUT}/grid/small.yaml)
    set(_fixture grid_scene)
  endif()
  # The condensed (default) runs that test/CMakeLists.txt does not make already.
  set(_extra)
  if(scene STREQUAL "lap_rows")
    set(_extra 4)
  elseif(scene STREQUAL "double_lap")
    set(_extra 3 4)
  elseif(scene STREQUAL "plate_grid")
    set(_extra 1 2 3 4)
  elseif(scene STREQUAL "plate_grid_small")
    set(_extra 4)
  endif()
  foreach(ranks ${_extra})
    boltnet_run(${scene} ${ranks} ${_scene} ${_args})
  endforeach()
  foreach(ranks 1 2 3 4)
    boltnet_run(${scene}_whole ${ranks} ${_scene} -patch_condense false ${_args})
    if(_fixture)
      set_tests_properties(run_${scene}_whole_np${ranks} PROPERTIES FIXTURES_REQUIRED ${_fixture})
      if(ranks IN_LIST _extra)
        set_tests_properties(run_${scene}_np${ranks} PROPERTIES FIXTURES_REQUIRED ${_fixture})
      endif()
    endif()
    add_test(NAME ${scene}_condensed_np${ranks}_vs_whole
      COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/${scene}_whole_np1/joints.csv ${BOLTNET_OUT}/${scene}_np${ranks}/joints.csv 1e-8)
    set_tests_properties(${scene}_condensed_np${ranks}_vs_whole PROPERTIES FIXTURES_REQUIRED "${scene}_whole_np1;${scene}_np${ranks}")
    if(ranks GREATER 1)
      add_test(NAME ${scene}_whole_np${ranks}_vs_np1
        COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/${scene}_whole_np1/joints.csv ${BOLTNET_OUT}/${scene}_whole_np${ranks}/joints.csv 1e-8)
      set_tests_properties(${scene}_whole_np${ranks}_vs_np1 PROPERTIES FIXTURES_REQUIRED "${scene}_whole_np1;${scene}_whole_np${ranks}")
    endif()
  endforeach()
endforeach()

# Some patches condensed, the others kept whole (-patch_condense auto, patch/layout.hpp): the same
# joints.csv as the whole model's 1-rank run. lap-rows' patches have 6 to 24 port dof over about
# 3,200 dof (ports per square root of dof 0.11 to 0.43): ratio 0.3 condenses the 4 plates of its
# one- and two-fastener laps and keeps the 4 of its three- and four-fastener laps whole. The small
# plate grid cut on 2 and 3 ranks has seams between patches whose ratios lie around 4: 4.0 condenses
# 3 of its 12 patches and keeps 9 whole, with both kinds on either side of the same seams.
foreach(ranks 1 2 3)
  boltnet_run(lap_rows_mixed ${ranks} ${BOLTNET_SCENES}/lap-rows.yaml -patch_condense_ratio 0.3)
  add_test(NAME lap_rows_mixed_np${ranks}_vs_whole
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/lap_rows_whole_np1/joints.csv ${BOLTNET_OUT}/lap_rows_mixed_np${ranks}/joints.csv 1e-8)
  set_tests_properties(lap_rows_mixed_np${ranks}_vs_whole PROPERTIES FIXTURES_REQUIRED "lap_rows_whole_np1;lap_rows_mixed_np${ranks}")
endforeach()
foreach(ranks 2 3)
  boltnet_run(plate_grid_small_mixed ${ranks} ${BOLTNET_OUT}/grid/small.yaml -patch_condense_ratio 4.0)
  set_tests_properties(run_plate_grid_small_mixed_np${ranks} PROPERTIES FIXTURES_REQUIRED grid_scene)
  add_test(NAME plate_grid_small_mixed_np${ranks}_vs_whole
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/plate_grid_small_whole_np1/joints.csv ${BOLTNET_OUT}/plate_grid_small_mixed_np${ranks}/joints.csv 1e-8)
  set_tests_properties(plate_grid_small_mixed_np${ranks}_vs_whole PROPERTIES FIXTURES_REQUIRED "plate_grid_small_whole_np1;plate_grid_small_mixed_np${ranks}")
endforeach()
# The rule itself, counted from the ports: lap-rows' plates with at most 0.3 sqrt(dof) port dof are
# those of its first two laps (6 and 12 port dof over about 3,200 dof; 0.3 sqrt(3,200) = 17), 4 of 8;
# the 3-rank grid's patches at ratio 4.0 are mixed (both kinds present).
add_test(NAME lap_rows_mixed_counts
  COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['condensed_patches'], 'of', s['patches'], 'patches condensed'); sys.exit(0 if s['condensed_patches'] == 4 and s['patches'] == 8 else 1)"
          ${BOLTNET_OUT}/lap_rows_mixed_np1/summary.json)
set_tests_properties(lap_rows_mixed_counts PROPERTIES FIXTURES_REQUIRED lap_rows_mixed_np1)
add_test(NAME plate_grid_small_mixed_counts
  COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['condensed_patches'], 'of', s['patches'], 'patches condensed'); sys.exit(0 if 0 < s['condensed_patches'] < s['patches'] else 1)"
          ${BOLTNET_OUT}/plate_grid_small_mixed_np3/summary.json)
set_tests_properties(plate_grid_small_mixed_counts PROPERTIES FIXTURES_REQUIRED plate_grid_small_mixed_np3)
# A value -patch_condense does not know is named.
boltnet_expect(patch_condense_bad_value 1 --fail --match "patch_condense maybe: expected auto, true or false"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${BOLTNET_OUT}/condense_bad -patch_condense maybe)

# The lagged interface solve (GMRES preconditioned by an earlier factorisation) solves the same
# Newton steps as the direct one: the same joints.csv to 1e-8 (GMRES stops at 1e-10 of the residual)
# on fig3b (contact, bearing in turn, cut patches on 2 ranks), on the frictional chain and on a small
# plate grid (below).
boltnet_run(fig3b_lagged 2 ${BOLTNET_SCENES}/fig3b.yaml -load_steps 30 -interface_solve lagged)
add_test(NAME fig3b_lagged_same_as_direct
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/fig3b_np2/joints.csv ${BOLTNET_OUT}/fig3b_lagged_np2/joints.csv 1e-8)
set_tests_properties(fig3b_lagged_same_as_direct PROPERTIES FIXTURES_REQUIRED "fig3b_np2;fig3b_lagged_np2")
boltnet_run(chain_lagged 1 ${BOLTNET_TEST_SCENES}/chain.yaml -interface_solve lagged)
add_test(NAME chain_lagged_same_as_direct
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/chain_np1/joints.csv ${BOLTNET_OUT}/chain_lagged_np1/joints.csv 1e-8)
set_tests_properties(chain_lagged_same_as_direct PROPERTIES FIXTURES_REQUIRED "chain_np1;chain_lagged_np1")
# A singular Jacobian is still named when GMRES, not the factorisation, is the first to fail.
boltnet_expect(singular_tangent_named_lagged 1 --fail
  --match "FAILED: Load step 1 .*DIVERGED_LINEAR_SOLVE.*the Jacobian is singular: 2 null pivots.*it moves patch 1 \\(ux,uy of 1 node\\). across joint 0 \\(t1,t2\\)"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/kg0_lagged -joint_bolt_law contact -joint_bolt_kt 0 -interface_solve lagged)
# The small plate grid (6 plates, 14 frictional fasteners, joints leaving stick at every step): the
# lagged solve gives the direct solve's joints.csv and factors fewer times than it solves.
boltnet_run(plate_grid_small_lagged 2 ${BOLTNET_OUT}/grid/small.yaml -interface_solve lagged)
set_tests_properties(run_plate_grid_small_lagged_np2 PROPERTIES FIXTURES_REQUIRED grid_scene)
add_test(NAME plate_grid_small_lagged_same_as_direct
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/plate_grid_small_np2/joints.csv ${BOLTNET_OUT}/plate_grid_small_lagged_np2/joints.csv 1e-8)
set_tests_properties(plate_grid_small_lagged_same_as_direct PROPERTIES FIXTURES_REQUIRED "plate_grid_small_np2;plate_grid_small_lagged_np2")
add_test(NAME plate_grid_small_lagged_factors_less
  COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['lagged_factorisations'], 'factorisations for', s['linear_solves'], 'linear solves'); sys.exit(0 if s['interface_solve'] == 'lagged' and 0 < s['lagged_factorisations'] < s['linear_solves'] else 1)"
          ${BOLTNET_OUT}/plate_grid_small_lagged_np2/summary.json)
set_tests_properties(plate_grid_small_lagged_factors_less PROPERTIES FIXTURES_REQUIRED plate_grid_small_lagged_np2)

# -interface_solve auto (the default) decides from MUMPS's analysis of the first Jacobian: lagged
# where the factorisation costs at least -interface_lagged_flops_per_entry flops per entry of the
# factors (docs/solver.md, "The interface solve"). The small scenes' factorisations cost far less
# (13 to 300 flops per entry), so they stay direct: the chain's default run says so.
add_test(NAME chain_auto_is_direct
  COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['interface_solve']); sys.exit(0 if s['interface_solve'] == 'direct' and s['lagged_factorisations'] == 0 else 1)"
          ${BOLTNET_OUT}/chain_np1/summary.json)
set_tests_properties(chain_auto_is_direct PROPERTIES FIXTURES_REQUIRED chain_np1)
# With the threshold at 1 flop per entry every analysis qualifies: the run says it went lagged,
# factors once for the whole load path, and gives the direct solve's joints.csv (to 1e-8: GMRES
# stops at 1e-10 of the residual) on 1 rank (the chain) and on 2 and 3 ranks (the small plate grid,
# against its direct run on 2 ranks).
boltnet_expect(chain_auto_lagged 1 --match "MUMPS's analysis estimates the 36-dof Jacobian's factorisation at [0-9]+ flops per entry of its factors \\(-interface_lagged_flops_per_entry 1\\.?\\): the interface solve is lagged"
  --match "steps converged" -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/chain.yaml -output_dir ${BOLTNET_OUT}/chain_auto_lagged
  -interface_lagged_flops_per_entry 1)
set_tests_properties(chain_auto_lagged_np1 PROPERTIES FIXTURES_SETUP chain_auto_lagged)
add_test(NAME chain_auto_lagged_same_as_direct
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/chain_np1/joints.csv ${BOLTNET_OUT}/chain_auto_lagged/joints.csv 1e-8)
set_tests_properties(chain_auto_lagged_same_as_direct PROPERTIES FIXTURES_REQUIRED "chain_np1;chain_auto_lagged")
add_test(NAME chain_auto_lagged_factors_once
  COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['interface_solve'], s['lagged_factorisations'], 'factorisations for', s['linear_solves'], 'linear solves'); sys.exit(0 if s['interface_solve'] == 'lagged' and s['lagged_factorisations'] == 1 and s['linear_solves'] > 1 else 1)"
          ${BOLTNET_OUT}/chain_auto_lagged/summary.json)
set_tests_properties(chain_auto_lagged_factors_once PROPERTIES FIXTURES_REQUIRED chain_auto_lagged)
foreach(ranks 2 3)
  boltnet_run(plate_grid_small_auto_lagged ${ranks} ${BOLTNET_OUT}/grid/small.yaml -interface_lagged_flops_per_entry 1)
  set_tests_properties(run_plate_grid_small_auto_lagged_np${ranks} PROPERTIES FIXTURES_REQUIRED grid_scene)
  add_test(NAME plate_grid_small_auto_lagged_np${ranks}_same_as_direct
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/plate_grid_small_np2/joints.csv ${BOLTNET_OUT}/plate_grid_small_auto_lagged_np${ranks}/joints.csv 1e-8)
  set_tests_properties(plate_grid_small_auto_lagged_np${ranks}_same_as_direct PROPERTIES FIXTURES_REQUIRED "plate_grid_small_np2;plate_grid_small_auto_lagged_np${ranks}")
endforeach()
# Factors on disk are read back at every triangular solve, and a Krylov method the user chose is
# the user's: with either, auto stays direct at an estimate that makes it lagged in core. (Factors on disk: lap-rows in
# the global system, whose in-core estimate, 55 MB, is above the 30 MB given, as in
# test/memory_tests.cmake's factor_memory_estimate.)
boltnet_expect(lap_rows_auto_on_disk_direct 1 --match "the factors go to disk" --match "steps converged" --reject "the interface solve is lagged"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${BOLTNET_OUT}/lap_rows_auto_on_disk
  -output_fields false -patch_condense false -interface_lagged_flops_per_entry 1 -interface_memory_mb 30)
set_tests_properties(lap_rows_auto_on_disk_direct_np1 PROPERTIES FIXTURES_SETUP lap_rows_auto_on_disk)
boltnet_expect(chain_auto_user_ksp_direct 1 --match "steps converged" --reject "the interface solve is lagged"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/chain.yaml -output_dir ${BOLTNET_OUT}/chain_auto_user_ksp
  -interface_lagged_flops_per_entry 1 -ksp_type gmres)
set_tests_properties(chain_auto_user_ksp_direct_np1 PROPERTIES FIXTURES_SETUP chain_auto_user_ksp)
# With factors on disk auto needs a dearer factorisation (-interface_lagged_flops_per_entry_on_disk:
# the full junction's 4,480 flops per entry against the default 2,500) and Eisenstat-Walker's
# tolerances, which keep GMRES to a few solves per Newton iteration. Both at 1 flop per entry,
# lap-rows goes lagged on disk, one factorisation, and keeps the closed-form load shares, on 1, 2
# and 3 ranks; with -snes_ksp_ew false it stays direct.
foreach(ranks 1 2 3)
  set(out ${BOLTNET_OUT}/lap_rows_auto_on_disk_lagged_np${ranks})
  boltnet_expect(lap_rows_auto_on_disk_lagged ${ranks} --match "the factors go to disk" --match "the interface solve is lagged" --match "steps converged"
    -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${out}
    -output_fields false -patch_condense false -interface_lagged_flops_per_entry 1 -interface_lagged_flops_per_entry_on_disk 1 -interface_memory_mb 30)
  set_tests_properties(lap_rows_auto_on_disk_lagged_np${ranks} PROPERTIES FIXTURES_SETUP lap_rows_auto_on_disk_lagged_np${ranks})
  add_test(NAME lap_rows_auto_on_disk_lagged_summary_np${ranks}
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['interface_solve'], s['factors_on_disk'], s['ksp_ew'], s['lagged_factorisations'], s['factor_flops_per_entry']); sys.exit(0 if s['interface_solve'] == 'lagged' and s['factors_on_disk'] and s['ksp_ew'] and s['lagged_factorisations'] == 1 and s['factor_flops_per_entry'] > 1 else 1)"
            ${out}/summary.json)
  add_test(NAME lap_rows_auto_on_disk_lagged_load_shares_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_lap_rows.py ${out}/joints.csv 21820 72000 20 1.27 20)
  set_tests_properties(lap_rows_auto_on_disk_lagged_summary_np${ranks} lap_rows_auto_on_disk_lagged_load_shares_np${ranks}
    PROPERTIES FIXTURES_REQUIRED lap_rows_auto_on_disk_lagged_np${ranks})
endforeach()
boltnet_expect(lap_rows_auto_no_ew_on_disk_direct 1 --match "the factors go to disk" --match "steps converged" --reject "the interface solve is lagged"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${BOLTNET_OUT}/lap_rows_auto_no_ew_on_disk
  -output_fields false -patch_condense false -interface_lagged_flops_per_entry 1 -interface_lagged_flops_per_entry_on_disk 1 -interface_memory_mb 30 -snes_ksp_ew false)
set_tests_properties(lap_rows_auto_no_ew_on_disk_direct_np1 PROPERTIES FIXTURES_SETUP lap_rows_auto_no_ew_on_disk)
foreach(case lap_rows_auto_on_disk lap_rows_auto_no_ew_on_disk chain_auto_user_ksp)
  add_test(NAME ${case}_is_direct
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['interface_solve'], s['factors_on_disk'], 'ksp_ew', s['ksp_ew']); sys.exit(0 if s['interface_solve'] == 'direct' and s['lagged_factorisations'] == 0 and s['factors_on_disk'] == sys.argv[2].endswith('on_disk') and not s['ksp_ew'] else 1)"
            ${BOLTNET_OUT}/${case}/summary.json ${case})
  set_tests_properties(${case}_is_direct PROPERTIES FIXTURES_REQUIRED ${case})
endforeach()
boltnet_expect(interface_lagged_flops_bad 1 --fail --max-lines 1 --match "-interface_lagged_flops_per_entry 0\\.? must be > 0"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/chain.yaml -output_dir ${BOLTNET_OUT}/lagged_flops_bad -interface_lagged_flops_per_entry 0)
boltnet_expect(interface_lagged_flops_on_disk_bad 1 --fail --max-lines 1 --match "-interface_lagged_flops_per_entry_on_disk -3\\.? must be > 0"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/chain.yaml -output_dir ${BOLTNET_OUT}/lagged_flops_on_disk_bad -interface_lagged_flops_per_entry_on_disk -3)
boltnet_expect(interface_solve_bad 1 --fail --match "auto" --match "direct" --match "lagged"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/chain.yaml -output_dir ${BOLTNET_OUT}/interface_solve_bad -interface_solve sometimes)

# -log_view says where the time goes: boltnet's stages (lib/core/log.hpp) are listed, and the
# condensation, the interface solve and the output took time in theirs (a stage that no code pushes
# shows 0.0000e+00), with the condensation's own events called, on 1, 2 and 3 ranks. Every patch condensed, so that the interior recovery runs
# on every rank count (the automatic choice keeps fig3b's cut pieces whole on 2 and 3 ranks).
foreach(ranks 1 2 3)
  boltnet_expect(log_view_stages ${ranks} --match "Boltnet Set-up: " --match "Boltnet Condense: [1-9]" --match "Boltnet Solve: [1-9]"
                 --match "Boltnet Output: [1-9]" --match "BoltnetCondense" --match "BoltnetRecover"
                 --match "BoltnetPatchMatrix +[1-9]" --match "BoltnetSchur +[1-9]" --match "BoltnetElementResults +[1-9]"
                 -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3b.yaml
                 -output_dir ${BOLTNET_OUT}/log_view_stages_np${ranks} -log_view -patch_condense true)
endforeach()

# A solve that stops on a hard error inside PCSetUp (a solver type PETSc does not have) still lists
# the interface solve's event in -log_view: the stepper ends it before the error goes on
# (solver/stepper.cpp, SolveInStage). Without that, the event was never logged.
foreach(ranks 1 2)
  boltnet_expect(log_view_failed_solve ${ranks} --fail --match "Could not locate solver type nonexistent"
                 --match "BoltnetInterfaceSolve +1 "
                 -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml
                 -output_dir ${BOLTNET_OUT}/log_view_failed_solve_np${ranks} -output_fields false -pc_factor_mat_solver_type nonexistent -log_view)
endforeach()
# Without -log_view the same run reports PETSc's error alone.
boltnet_expect(failed_solve_no_log 1 --fail --match "Could not locate solver type nonexistent" --reject "log_view"
               -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml
               -output_dir ${BOLTNET_OUT}/failed_solve_no_log -output_fields false -pc_factor_mat_solver_type nonexistent)

# The interface's ordering (-interface_choose_ordering, docs/solver.md, "What a factorisation of the
# interface costs"): on a 16 x 4 plate grid QAMD's factorisation is the cheapest, 0.83 of the flops
# of MUMPS's own choice (PORD here), and the run must pick it and factor with it; on the 12 x 2 grid
# QAMD's is 0.925 of MUMPS's own choice (AMF there), under the tenth that a change of ordering needs,
# and MUMPS's own choice must stay. The reference is MUMPS's analysis with each ordering given by the user (-mat_mumps_icntl_7 7,
# 6, 2), whose flops the trials must reproduce and whose joints.csv the chosen run must equal; a
# user's ordering leaves boltnet no choice (check_ordering.py). 1, 2 and 3 ranks.
add_test(NAME make_plate_grid_16x4
  COMMAND ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/make-plate-grid ${BOLTNET_OUT}/grid g16x4 --nx 16 --ny 4)
set_tests_properties(make_plate_grid_16x4 PROPERTIES FIXTURES_SETUP grid_16x4)
foreach(ranks 1 2 3)
  add_test(NAME interface_ordering_chosen_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_ordering.py ${BOLTNET_OUT}/ordering_np${ranks} ${BOLTNET_OUT}/grid/g16x4.yaml
            -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver>)
  set_tests_properties(interface_ordering_chosen_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED grid_16x4)
endforeach()
add_test(NAME interface_ordering_kept_np1
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_ordering.py ${BOLTNET_OUT}/ordering_kept ${BOLTNET_OUT}/grid/long.yaml
          -- $<TARGET_FILE:boltnet_driver>)
set_tests_properties(interface_ordering_kept_np1 PROPERTIES ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED grid_long)

# The interface solve's own event (BoltnetInterfaceSolve, KSP's pre- and post-solve hooks) holds
# every Newton iteration's linear solve with its factorisation: as many calls as PETSc's KSPSolve,
# and at least the time of PCSetUp and KSPSolve together (check_interface_event.py), with the
# direct solve (fig3a) and the lagged one (the small plate grid, GMRES on a kept factorisation).
# One rank, where the -log_view times are that rank's own.
add_test(NAME log_view_interface_solve_direct
  COMMAND sh -c "rm -rf \"$2\" && \"$0\" -scene \"$1\" -output_dir \"$2\" -output_fields false -log_view :\"$2.log\" > /dev/null && \"$3\" \"$4\" \"$2.log\""
          $<TARGET_FILE:boltnet_driver> ${BOLTNET_SCENES}/fig3a.yaml ${BOLTNET_OUT}/log_view_interface_direct ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_interface_event.py)
set_tests_properties(log_view_interface_solve_direct PROPERTIES ENVIRONMENT "${BOLTNET_ENV}")
add_test(NAME log_view_interface_solve_lagged
  COMMAND sh -c "rm -rf \"$2\" && \"$0\" -scene \"$1\" -output_dir \"$2\" -output_fields false -interface_solve lagged -log_view :\"$2.log\" > /dev/null && \"$3\" \"$4\" \"$2.log\""
          $<TARGET_FILE:boltnet_driver> ${BOLTNET_OUT}/grid/small.yaml ${BOLTNET_OUT}/log_view_interface_lagged ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_interface_event.py)
set_tests_properties(log_view_interface_solve_lagged PROPERTIES ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED grid_scene)

# -snes_ksp_ew still reaches every linear solve: the interface event's hooks take the place of
# SNES's own KSP hooks (KSPPreSolve_SNESEW, where Eisenstat-Walker sets the tolerance) and must
# call them. PETSc reports each tolerance it sets under -info; check_ksp_ew.py checks one per
# linear solve, the first of each step at rtol_0 and none above rtol_max (PETSc's definition of the
# method). The lagged solve on the small grid, where GMRES uses the tolerance; 1 to 3 ranks:
# - lagged_snes_ksp_ew: given, with -snes_ksp_ew_rtol0 0.25 (PETSc's rtol_max, 0.9);
# - lagged_default_ksp_ew: not given, the lagged solve's default (solver/stepper.cpp,
#   AssemblyDefaultEW): PETSc's rtol_0, 0.3, and boltnet's rtol_max, 0.5. The joints stay the
#   direct solve's: the *_lagged_same_as_direct tests above run with these defaults.
foreach(case "lagged_snes_ksp_ew;lagged_ksp_ew;-snes_ksp_ew -snes_ksp_ew_rtol0 0.25;0.25 0.9" "lagged_default_ksp_ew;lagged_default_ksp_ew;;0.3 0.5")
  list(GET case 0 name)
  list(GET case 1 dir)
  list(GET case 2 opts)
  list(GET case 3 rtols)
  foreach(ranks 1 2 3)
    add_test(NAME ${name}_np${ranks}
      COMMAND sh -c "rm -rf \"$3\" && \"$0\" -n $1 --oversubscribe \"$2\" -scene \"$4\" -output_dir \"$3\" -output_fields false -interface_solve lagged $7 -info \"$3.info:snes\" > \"$3.log\" && \"$5\" \"$6\" \"$3.info.0\" \"$3/summary.json\" $8"
              ${MPIEXEC_EXECUTABLE} ${ranks} $<TARGET_FILE:boltnet_driver> ${BOLTNET_OUT}/${dir}_np${ranks} ${BOLTNET_OUT}/grid/small.yaml ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_ksp_ew.py "${opts}" "${rtols}")
    set_tests_properties(${name}_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED grid_scene)
  endforeach()
endforeach()
# The user's tolerance wins: with -ksp_rtol or -snes_ksp_ew false no solve gets an Eisenstat-Walker
# tolerance; nor does the direct solve, which has no Krylov tolerance to set.
foreach(case "rtol;-interface_solve lagged -ksp_rtol 1e-10" "ew_false;-interface_solve lagged -snes_ksp_ew false" "direct;-interface_solve direct")
  list(GET case 0 name)
  list(GET case 1 opts)
  add_test(NAME lagged_no_ksp_ew_${name}
    COMMAND sh -c "rm -rf \"$1\" && \"$0\" -scene \"$2\" -output_dir \"$1\" -output_fields false $5 -info :snes > \"$1.log\" && \"$3\" \"$4\" \"$1.log\" \"$1/summary.json\" none"
            $<TARGET_FILE:boltnet_driver> ${BOLTNET_OUT}/lagged_no_ksp_ew_${name} ${BOLTNET_OUT}/grid/small.yaml ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_ksp_ew.py "${opts}")
  set_tests_properties(lagged_no_ksp_ew_${name} PROPERTIES ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED grid_scene)
endforeach()
