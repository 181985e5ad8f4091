# Trusting "converged" and the joint-law edge cases (docs/solver.md "When is a step converged",
# docs/joint-laws.md). Each case used to end in a false convergence or a failure; each test compares
# with the closed form of the 1D problem, or asserts the failure and its message. Included by
# CMakeLists.txt.
set(_hard ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_hard.py)

# A huge axial stiffness (kn = 1e18) inflates ||J|| ||x||: the round-off test accepted a joint force of
# 5,722 N at 6,000 N. Convergence is judged against the force scale: the whole fig3c cycle follows the
# closed form (check_fig3c.py, rtol 1e-9), on 1 and 2 ranks.
foreach(ranks 1 2)
  boltnet_run(trust_stiff_kn ${ranks} ${BOLTNET_SCENES}/fig3c.yaml -joint_bolt_kn 1e18)
  add_test(NAME trust_stiff_kn_closed_form_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fig3c.py ${BOLTNET_OUT}/trust_stiff_kn_np${ranks}/joints.csv 1.5e5 5000 4e4 0.05 3000)
  set_tests_properties(trust_stiff_kn_closed_form_np${ranks} PROPERTIES FIXTURES_REQUIRED trust_stiff_kn_np${ranks})
endforeach()

# A mechanism: fig3a with the contact law and kc = 0 carries at most k j = 450 N (beyond the clearance
# the force stays k j). It used to "converge" at 500 N with a jump of -3e7 mm and the force of the
# wrong sign. Now MUMPS finds the null pivot, the steps are cut back towards 450 N (the closed form's
# limit: the last step that converges starts at or within 2^-8 of a step below it), and the run
# stops naming the mechanism: plate 1 sliding in x across joint 0's t1; the same on 1, 2 and 3 ranks.
foreach(ranks 1 2 3)
  boltnet_expect(trust_mechanism_named ${ranks} --fail --match "FAILED: Load step [0-9]+ from load factor 4(49\\.[0-9]+|50) to"
    --match "the Jacobian is singular: 1 null pivot .* it moves patch 1 \\(ux( of 190 nodes)?\\). across joint 0 \\(t1\\)"
    -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml
    -output_dir ${BOLTNET_OUT}/trust_mechanism_np${ranks} -joint_bolt_kc 0)
endforeach()
# On shell patches a joint with no stiffness (contact, kt = 0, clearance open) is named too.
boltnet_expect(trust_mechanism_shell_joint_named 1 --fail --match "FAILED: Load step 1 .*DIVERGED_LINEAR_SOLVE"
  --match "it moves patch 1 \\(ux( of 190 nodes)?\\). across joint 0 \\(t1\\)"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml -output_dir ${BOLTNET_OUT}/trust_shell_kt0 -joint_bolt_kt 0)

# The balance check after every converged step: a tolerance loosened by hand (-snes_atol 1e4 > the
# load) lets SNES stop at the starting point, where the out-of-balance force is the whole load
# (6000 N, ratio 1); the step is not accepted and the run stops saying why.
boltnet_expect(trust_balance_checked 1 --fail
  --match "CONVERGED_FNORM_ABS but not in balance: out-of-balance force 6e\\+03 = 1 of the force scale 6e\\+03"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/trust_balance
  -snes_atol 1e4 -load_path ramp -load_max 6000 -load_steps 1 -load_max_cuts 0)

# Pure Coulomb (kg = 0) under a prescribed force with a large clearance (0.5 mm): the residual is flat
# while the bolt slides, and the Newton step (set by the tangent's floor) ended 0.2 mm short of the
# bearing; the line search now lengthens it to the state change. 3000 -> 3010 N in one step lands on
# du = G/ke + j + 10/kc = 0.52025 mm, bearing.
boltnet_run(trust_coulomb_wide_gap 1 ${BOLTNET_SCENES}/fig3c.yaml -joint_bolt_kg 0 -joint_bolt_gap 0.5 -load_table 3000,3010 -load_steps 1)
add_test(NAME trust_coulomb_wide_gap_closed_form
  COMMAND ${_hard} force1d ${BOLTNET_OUT}/trust_coulomb_wide_gap_np1/joints.csv 1.5e5 0 4e4 0.5 3000 --states stick,contact --only)
set_tests_properties(trust_coulomb_wide_gap_closed_form PROPERTIES FIXTURES_REQUIRED trust_coulomb_wide_gap_np1)
# The same for an M20 bolt identified from its geometry in a 22 mm hole (j = 1 mm, kg = 0), 100 N
# past its slip load G = 22.5 kN, against the closed form with the identified parameters.
boltnet_run(trust_m20 1 ${BOLTNET_TEST_SCENES}/m20-geometry.yaml)
add_test(NAME trust_m20_closed_form
  COMMAND sh -c "\"$0\" -fastener_d 20 -fastener_hole 22 -fastener_t1 10 -fastener_t2 10 -fastener_E1 72000 -fastener_E2 72000 -fastener_Ef 210000 -fastener_torque 300000 -fastener_mu 0.3 > \"$1/identify.txt\" && ${BOLTNET_PYTHON} \"$2\" \"$1/summary.json\" \"$1/joints.csv\" \"$1/identify.txt\" \"$3\" force1d --states stick,contact --only"
          $<TARGET_FILE:boltnet_identify> ${BOLTNET_OUT}/trust_m20_np1 ${CMAKE_CURRENT_SOURCE_DIR}/check_identified_scene.py ${CMAKE_CURRENT_SOURCE_DIR}/check_hard.py)
set_tests_properties(trust_m20_closed_form PROPERTIES FIXTURES_REQUIRED trust_m20_np1)

# 0 < kg < 1e-3 ke with no bearing in reach (kg = kc = 15 N/mm = 1e-4 ke, gap 100 mm): the floor used
# to stiffen the tangent to 150 N/mm, each Newton step went a tenth of the way, and 50 did not
# converge. kg is its own tangent now: slip (T - G)/kg = 6.667 mm, du = 6.687 mm.
boltnet_run(trust_near_coulomb 1 ${BOLTNET_SCENES}/fig3c.yaml -joint_bolt_kg 15 -joint_bolt_kc 15 -joint_bolt_gap 100 -load_table 3000,3100 -load_steps 1)
add_test(NAME trust_near_coulomb_closed_form
  COMMAND ${_hard} force1d ${BOLTNET_OUT}/trust_near_coulomb_np1/joints.csv 1.5e5 15 15 100 3000 --states stick,slide --only)
set_tests_properties(trust_near_coulomb_closed_form PROPERTIES FIXTURES_REQUIRED trust_near_coulomb_np1)

# The contact law without clearance and kt = 0 is F = kc du for every du; at du = 0 its tangent was
# kt = 0 (a singular Jacobian at rest). Rigid (fig3c) and shell (fig3a) patches, the whole load cycle.
boltnet_run(trust_contact_no_gap 1 ${BOLTNET_SCENES}/fig3c.yaml -joint_bolt_law contact -joint_bolt_kt 0 -joint_bolt_gap 0)
add_test(NAME trust_contact_no_gap_closed_form
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_contact.py ${BOLTNET_OUT}/trust_contact_no_gap_np1/joints.csv 0 4e4 0 1e-9)
set_tests_properties(trust_contact_no_gap_closed_form PROPERTIES FIXTURES_REQUIRED trust_contact_no_gap_np1)
boltnet_run(trust_contact_no_gap_shell 2 ${BOLTNET_SCENES}/fig3a.yaml -joint_bolt_kt 0 -joint_bolt_gap 0)
add_test(NAME trust_contact_no_gap_shell_closed_form
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_contact.py ${BOLTNET_OUT}/trust_contact_no_gap_shell_np2/joints.csv 0 4e4 0)
set_tests_properties(trust_contact_no_gap_shell_closed_form PROPERTIES FIXTURES_REQUIRED trust_contact_no_gap_shell_np2)

# A force on a fixed dof (the pulling force put on the clamped node set by mistake) used to vanish
# into the support, and the run converged with zero displacement: it is an error naming the set.
foreach(ranks 1 3)
  boltnet_expect(trust_force_on_fixed ${ranks} --fail --match "Patch 1: a force on ux of node set 'xmin' is applied to a dof that is also fixed"
    -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml
    -scene_bcs ${BOLTNET_TEST_SCENES}/force-on-fixed.bcs.csv -output_dir ${BOLTNET_OUT}/trust_force_on_fixed)
endforeach()

# The round-off test's |J| |x| is computed from J's own arrays (no copy of |J|: lib/solver/roundoff.hpp):
# against MatMult with an explicit |A| of a random matrix whose rows reach every rank, to 1e-14 per
# row, on 1 to 3 ranks (test/test_abs_mult.cpp).
add_executable(test_abs_mult test_abs_mult.cpp ${PROJECT_SOURCE_DIR}/lib/solver/roundoff.cpp)
target_include_directories(test_abs_mult PRIVATE ${PROJECT_SOURCE_DIR}/lib)
target_link_libraries(test_abs_mult PRIVATE PkgConfig::PETSC MPI::MPI_C)
foreach(ranks 1 2 3)
  boltnet_expect(abs_mult ${ranks} --match "test_abs_mult: PASS" --
    ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:test_abs_mult>)
endforeach()
