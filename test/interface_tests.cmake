# The interface: condensed patches against patches kept whole, and the lagged interface solve
# against the direct one (docs/solver.md, "Condensed patches", "The interface solve").
#
# Condensation changes how the model is solved, not the model: every shipped shell scene gives the
# same joints.csv with -patch_condense false (forces to 1e-8 of the largest, the solver's
# tolerance; states identical: compare_csv.py compares them as words), on 1 rank and on the largest
# rank count of its default runs, which are compared against the uncondensed 1-rank run too.
foreach(scene fig3a fig3b lap_rows double_lap)
  string(REPLACE "_" "-" file ${scene})
  set(_args)
  if(scene STREQUAL "fig3b")
    set(_args -load_steps 30) # as its default runs (test/CMakeLists.txt)
  endif()
  set(_most 4)
  if(scene STREQUAL "lap_rows")
    set(_most 3)
  elseif(scene STREQUAL "double_lap")
    set(_most 2)
  endif()
  foreach(ranks 1 ${_most})
    boltnet_run(${scene}_whole ${ranks} ${BOLTNET_SCENES}/${file}.yaml -patch_condense false ${_args})
  endforeach()
  foreach(ranks 1 ${_most})
    add_test(NAME ${scene}_condensed_np${ranks}_vs_whole
      COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/${scene}_whole_np1/joints.csv ${BOLTNET_OUT}/${scene}_np${ranks}/joints.csv 1e-8)
    set_tests_properties(${scene}_condensed_np${ranks}_vs_whole PROPERTIES FIXTURES_REQUIRED "${scene}_whole_np1;${scene}_np${ranks}")
  endforeach()
  add_test(NAME ${scene}_whole_np${_most}_vs_np1
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/${scene}_whole_np1/joints.csv ${BOLTNET_OUT}/${scene}_whole_np${_most}/joints.csv 1e-8)
  set_tests_properties(${scene}_whole_np${_most}_vs_np1 PROPERTIES FIXTURES_REQUIRED "${scene}_whole_np1;${scene}_whole_np${_most}")
endforeach()

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
