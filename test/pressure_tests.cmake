# Pressure on shell parts (bcs kind `pressure`, docs/scenes.md "Pressure").

# The consistent nodal forces (lib/patch/loads.cpp): resultant and moment against p A n and its
# moment on quadrilaterals, triangles and a mix, flat and tilted, on the whole part and on a node set,
# whole and cut into patches (the elements on the cuts shared by several patches).
add_executable(test_pressure_loads test_pressure_loads.cpp)
target_include_directories(test_pressure_loads PRIVATE ${PROJECT_SOURCE_DIR}/lib)
target_link_libraries(test_pressure_loads PRIVATE boltnet GTest::gtest PkgConfig::PETSC MPI::MPI_C)
gtest_discover_tests(test_pressure_loads)

# A square plate under uniform pressure, its centre deflection against Kirchhoff's closed form
# (test/check_plate_pressure.py): clamped, and simply supported, on 1, 2 and 3 ranks, cut into 9
# patches (elements shared across the cuts, the pressure on interior nodes condensed), and kept whole
# (-patch_condense false); MITC3+ triangles within their mesh error (1.0 % on this grid). The runs on
# 2 and 3 ranks also give 1 rank's joints.csv.
set(_plate ${BOLTNET_TEST_SCENES}/plate-pressure.yaml)
set(_plate_check ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_plate_pressure.py --a 100 --t 1 --E 70000 --nu 0.3 --q 0.01)
foreach(ranks 1 2 3)
  boltnet_run(plate_pressure ${ranks} ${_plate} -patch_max_nodes 60)
  add_test(NAME plate_pressure_clamped_np${ranks} COMMAND ${_plate_check} ${BOLTNET_OUT}/plate_pressure_np${ranks}/joints.csv --support clamped --rtol 1e-3)
  set_tests_properties(plate_pressure_clamped_np${ranks} PROPERTIES FIXTURES_REQUIRED plate_pressure_np${ranks})
endforeach()
boltnet_compare_ranks(plate_pressure 1e-9 2 3)
boltnet_run(plate_pressure_whole 2 ${_plate} -patch_max_nodes 60 -patch_condense false)
add_test(NAME plate_pressure_whole_clamped_np2 COMMAND ${_plate_check} ${BOLTNET_OUT}/plate_pressure_whole_np2/joints.csv --support clamped --rtol 1e-3)
set_tests_properties(plate_pressure_whole_clamped_np2 PROPERTIES FIXTURES_REQUIRED plate_pressure_whole_np2)
boltnet_run(plate_pressure_simple 2 ${_plate} -patch_max_nodes 60 -scene_bcs ${BOLTNET_TEST_SCENES}/plate-pressure-simple.bcs.csv)
add_test(NAME plate_pressure_simple_np2 COMMAND ${_plate_check} ${BOLTNET_OUT}/plate_pressure_simple_np2/joints.csv --support simple --rtol 1e-3)
set_tests_properties(plate_pressure_simple_np2 PROPERTIES FIXTURES_REQUIRED plate_pressure_simple_np2)
boltnet_run(plate_pressure_tri 3 ${_plate} -patch_max_nodes 60 -scene_patches ${BOLTNET_TEST_SCENES}/plate-pressure-tri.patches.csv)
add_test(NAME plate_pressure_tri_np3 COMMAND ${_plate_check} ${BOLTNET_OUT}/plate_pressure_tri_np3/joints.csv --support clamped --rtol 2e-2)
set_tests_properties(plate_pressure_tri_np3 PROPERTIES FIXTURES_REQUIRED plate_pressure_tri_np3)

# Bad pressures, named before anything is written: a dof other than 'all', a rigid patch, and a node
# set of a curve (no element lies in it).
set(_pbad ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:boltnet_driver> -output_dir ${BOLTNET_OUT}/bad -scene ${_plate})
boltnet_expect(bad_pressure_dof 2 ${_bad} --match "pressure-dof.bcs.csv line 4: a pressure acts along the elements' normals: its dof is 'all', not 'uz'"
  -- ${_pbad} -scene_bcs ${BOLTNET_TEST_SCENES}/pressure-dof.bcs.csv)
boltnet_expect(bad_pressure_rigid 2 ${_bad} --match "Pressure on patch 1: it is not a shell patch"
  -- ${_pbad} -scene_bcs ${BOLTNET_TEST_SCENES}/pressure-rigid.bcs.csv)
boltnet_expect(bad_pressure_curve 2 ${_bad} --match "Pressure on patch 0, node set 'ymax': no element has all its nodes in the set"
  -- ${_pbad} -scene_bcs ${BOLTNET_TEST_SCENES}/pressure-curve.bcs.csv)

# Pressure on a curved shell: an open tube (Gmsh quadrangles, test/make_tube_scene.py) under internal
# pressure, its radial and axial displacement against the membrane closed forms p R^2 / (E t) and
# -nu p R / (E t) x (test/check_tube_pressure.py; the 48 facets around put it 0.21 % low), on 1, 2
# and 3 ranks, cut into patches.
add_test(NAME pressure_make_tube COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/make_tube_scene.py ${BOLTNET_OUT}/tube)
set_tests_properties(pressure_make_tube PROPERTIES FIXTURES_SETUP tube_scene)
foreach(ranks 1 2 3)
  boltnet_run(tube_pressure ${ranks} ${BOLTNET_OUT}/tube/tube.yaml -patch_max_nodes 300)
  set_tests_properties(run_tube_pressure_np${ranks} PROPERTIES FIXTURES_REQUIRED tube_scene)
  add_test(NAME tube_pressure_closed_form_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_tube_pressure.py ${BOLTNET_OUT}/tube_pressure_np${ranks}/joints.csv
            --R 500 --L 1000 --t 2 --E 70000 --nu 0.3 --p 0.1 --rtol 5e-3)
  set_tests_properties(tube_pressure_closed_form_np${ranks} PROPERTIES FIXTURES_REQUIRED tube_pressure_np${ranks})
endforeach()
