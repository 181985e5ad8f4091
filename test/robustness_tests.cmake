# Hard-on-purpose cases of the robustness matrix (docs/robustness.md) that the
# default method (boltnet line search, consistent tangent, adaptive steps) passes: each asserts that the
# run converges and that it gives the reference values, so that a solver regression fails here. Cases
# the default does not pass yet are listed in docs/robustness.md, not tested. Included by CMakeLists.txt.
set(_hard ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_hard.py)
set(_fig3c_law 1.5e5 5000 4e4 0.05 3000)

# The load stops exactly at the friction threshold G = 3000 N and reverses to -G: the joint sticks
# throughout (|F - h(0)| <= G) and unloads over exactly 2G, in one step per segment and in twelve.
foreach(steps 1 12)
  boltnet_run(hard_threshold_${steps} 1 ${BOLTNET_SCENES}/fig3c.yaml -load_table 3000,-3000,0 -load_steps ${steps})
  add_test(NAME hard_threshold_${steps}_stays_stick
    COMMAND ${_hard} force1d ${BOLTNET_OUT}/hard_threshold_${steps}_np1/joints.csv ${_fig3c_law} --states stick --only)
  set_tests_properties(hard_threshold_${steps}_stays_stick PROPERTIES FIXTURES_REQUIRED hard_threshold_${steps}_np1)
endforeach()

# The clearance closes in one large step: 0 to 6 kN in one step goes through stick, slide and bearing
# and lands on the closed form (du = 0.13875 mm, bearing); the whole fig3c cycle at one step per segment.
boltnet_run(hard_clearance_one_step 1 ${BOLTNET_SCENES}/fig3c.yaml -load_path ramp -load_max 6000 -load_steps 1)
add_test(NAME hard_clearance_one_step_closed_form
  COMMAND ${_hard} force1d ${BOLTNET_OUT}/hard_clearance_one_step_np1/joints.csv ${_fig3c_law} --states contact --only)
set_tests_properties(hard_clearance_one_step_closed_form PROPERTIES FIXTURES_REQUIRED hard_clearance_one_step_np1)
boltnet_run(hard_cycle_one_step 1 ${BOLTNET_SCENES}/fig3c.yaml -load_steps 1)
add_test(NAME hard_cycle_one_step_closed_form
  COMMAND ${_hard} force1d ${BOLTNET_OUT}/hard_cycle_one_step_np1/joints.csv ${_fig3c_law} --states contact)
set_tests_properties(hard_cycle_one_step_closed_form PROPERTIES FIXTURES_REQUIRED hard_cycle_one_step_np1)
# fig3a (shells, contact law): each segment's clearance closes in one step.
boltnet_run(hard_fig3a_one_step 1 ${BOLTNET_SCENES}/fig3a.yaml -load_steps 1)
add_test(NAME hard_fig3a_one_step_contact_law
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_contact.py ${BOLTNET_OUT}/hard_fig3a_one_step_np1/joints.csv 4500 4e4 0.1)
set_tests_properties(hard_fig3a_one_step_contact_law PROPERTIES FIXTURES_REQUIRED hard_fig3a_one_step_np1)
# fig3a at 3 fixed steps per segment with l2's line search and no cut-backs: the third step's
# predicted start is its solution, and the rows of the dof that symmetry keeps at zero (u_y of the
# bolt's nodes) hold residuals of 1e-13 N, far above 100 eps (|J| |x|)_i of terms that nearly vanish.
# The round-off test judges them at the solution's size (docs/solver.md, "When is a step
# converged"); before it did, the 1-rank run stalled at that step on this machine (the residual
# hovering at -snes_atol; the 2- and 3-rank runs converged). The reference is the contact law's
# closed form.
foreach(ranks 1 2 3)
  boltnet_run(hard_fig3a_symmetry_rows ${ranks} ${BOLTNET_SCENES}/fig3a.yaml -load_steps 3 -load_max_cuts 0
              -snes_linesearch_type l2 -output_fields false)
  add_test(NAME hard_fig3a_symmetry_rows_np${ranks}_contact_law
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_contact.py ${BOLTNET_OUT}/hard_fig3a_symmetry_rows_np${ranks}/joints.csv 4500 4e4 0.1)
  set_tests_properties(hard_fig3a_symmetry_rows_np${ranks}_contact_law PROPERTIES FIXTURES_REQUIRED hard_fig3a_symmetry_rows_np${ranks})
endforeach()

# kg = 0 (pure Coulomb) under prescribed displacement, +-0.2 mm: the force saturates at G exactly while
# the bolt crosses its clearance, then bears (displacement-first closed form), in 60 and in 1 step per
# segment. Under force control: hard_coulomb_force below.
foreach(steps 1 60)
  boltnet_run(hard_coulomb_${steps} 1 ${BOLTNET_SCENES}/fig3c.yaml -scene_bcs ${BOLTNET_TEST_SCENES}/jenkins.bcs.csv
    -joint_bolt_kg 0 -load_table 0.2,-0.2,0 -load_steps ${steps})
  # one step per segment jumps from bearing to bearing and to stick; sixty pass through every state
  if(steps EQUAL 1)
    set(_states contact)
  else()
    set(_states stick,slide,contact)
  endif()
  add_test(NAME hard_coulomb_${steps}_closed_form
    COMMAND ${_hard} disp1d ${BOLTNET_OUT}/hard_coulomb_${steps}_np1/joints.csv 1.5e5 0 4e4 0.05 3000 --states ${_states})
  set_tests_properties(hard_coulomb_${steps}_closed_form PROPERTIES FIXTURES_REQUIRED hard_coulomb_${steps}_np1)
endforeach()

# kg = 0 (pure Coulomb) under a prescribed force, cycled to +-5 kN: past G the bolt slides across its
# whole clearance in one step and bears (no equilibrium in between); the slide tangent would be
# singular without the Jacobian's floor along the slip (kSlideFloor, lib/joint/law.hpp). The
# force-first closed form with kg = 0, at 1 and 12 steps per segment; only stick and bearing are
# equilibria.
foreach(steps 1 12)
  boltnet_run(hard_coulomb_force_${steps} 1 ${BOLTNET_SCENES}/fig3c.yaml -joint_bolt_kg 0 -load_table 5000,-5000,0 -load_steps ${steps})
  add_test(NAME hard_coulomb_force_${steps}_closed_form
    COMMAND ${_hard} force1d ${BOLTNET_OUT}/hard_coulomb_force_${steps}_np1/joints.csv 1.5e5 0 4e4 0.05 3000 --states stick,contact --only)
  set_tests_properties(hard_coulomb_force_${steps}_closed_form PROPERTIES FIXTURES_REQUIRED hard_coulomb_force_${steps}_np1)
endforeach()

# Symmetric joints that slide together: two identical joints in parallel on the symmetry axis carry
# half the load each, equal to round-off, through stick, slide and bearing both ways (fig3c's closed
# form at half the load); at 60 steps per segment and at 1, on 1 and 2 ranks.
foreach(steps 1 60)
  foreach(ranks 1 2)
    boltnet_run(hard_symmetric_${steps} ${ranks} ${BOLTNET_TEST_SCENES}/symmetric.yaml -load_steps ${steps})
    add_test(NAME hard_symmetric_${steps}_np${ranks}_halves
      COMMAND ${_hard} force1d ${BOLTNET_OUT}/hard_symmetric_${steps}_np${ranks}/joints.csv ${_fig3c_law} --share 0.5 --equal --states contact)
    set_tests_properties(hard_symmetric_${steps}_np${ranks}_halves PROPERTIES FIXTURES_REQUIRED hard_symmetric_${steps}_np${ranks})
  endforeach()
endforeach()

# Many joints changing state in the same step: chain in one step per segment (8 nonlinear joints leave
# stick or close a clearance in the first step) and the small plate grid in one step per segment. No
# closed form: the default must converge with no cut-back and give the same discrete solution as
# another method that converges there (l2 on chain, basic on the grid), to 1e-7 of each quantity's scale
# (the solves stop at 1e-10 of the residual: measured agreement 1e-9; a wrong state is off by far more).
boltnet_expect(hard_chain_one_step 1 --match "3 steps converged \\(0 cut-backs\\)"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/chain.yaml -output_dir ${BOLTNET_OUT}/hard_chain_one_step -load_steps 1)
set_tests_properties(hard_chain_one_step_np1 PROPERTIES FIXTURES_SETUP hard_chain_one_step)
boltnet_expect(hard_chain_one_step_l2 1 --match "3 steps converged \\(0 cut-backs\\)"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/chain.yaml -output_dir ${BOLTNET_OUT}/hard_chain_one_step_l2 -load_steps 1
  -load_max_cuts 0 -snes_linesearch_type l2)
set_tests_properties(hard_chain_one_step_l2_np1 PROPERTIES FIXTURES_SETUP hard_chain_one_step_l2)
add_test(NAME hard_chain_one_step_same_solution
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/hard_chain_one_step/joints.csv ${BOLTNET_OUT}/hard_chain_one_step_l2/joints.csv 1e-7)
set_tests_properties(hard_chain_one_step_same_solution PROPERTIES FIXTURES_REQUIRED "hard_chain_one_step;hard_chain_one_step_l2")
# The small plate grid (make_plate_grid_small's scene, which names basic: boltnet's line search is
# asked for explicitly) in one step to 8 kN and back: all 14 fasteners go from stick to bearing at once.
boltnet_expect(hard_grid_one_step 1 --match "2 steps converged \\(0 cut-backs\\)"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_OUT}/grid/small.yaml -output_dir ${BOLTNET_OUT}/hard_grid_one_step -load_steps 1
  -snes_linesearch_type boltnet -output_fields false)
set_tests_properties(hard_grid_one_step_np1 PROPERTIES FIXTURES_REQUIRED grid_scene FIXTURES_SETUP hard_grid_one_step)
boltnet_expect(hard_grid_one_step_basic 1 --match "2 steps converged \\(0 cut-backs\\)"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_OUT}/grid/small.yaml -output_dir ${BOLTNET_OUT}/hard_grid_one_step_basic -load_steps 1
  -load_max_cuts 0 -snes_linesearch_type basic -output_fields false)
set_tests_properties(hard_grid_one_step_basic_np1 PROPERTIES FIXTURES_REQUIRED grid_scene FIXTURES_SETUP hard_grid_one_step_basic)
add_test(NAME hard_grid_one_step_same_solution
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/hard_grid_one_step/joints.csv ${BOLTNET_OUT}/hard_grid_one_step_basic/joints.csv 1e-7)
set_tests_properties(hard_grid_one_step_same_solution PROPERTIES FIXTURES_REQUIRED "hard_grid_one_step;hard_grid_one_step_basic")
