# Keeping the factorisation while Newton converges (docs/solver.md, "Keeping the factorisation"):
# a modified Newton that changes how many factorisations a step costs, never the solution.
#
# fig3b (four bolts with growing clearances come into bearing one after the other), 30 steps per
# segment as its default runs, on 1 to 3 ranks, with the rule (-interface_keep_ratio 0.1, the
# default, given explicitly) and without it (0: a factorisation per Newton iteration). References:
# - the paper's figure 3b (check_fig3b.py): the bolts bear in the order of their clearances, and at
#   every step the four carry the applied load to 1e-7;
# - the run without the rule, for the joints (compare_csv.py, 1e-8 of each quantity's scale: the
#   iterations stop at different points within the tolerances), states identical;
# - fewer Jacobians assembled, hence factored, with the rule than without, and some kept
#   (summary.json's jacobians_assembled, jacobians_kept; measured on 1 to 3 ranks: 37 against 71 to 72).
foreach(ranks 1 2 3)
  foreach(keep 0.1 0)
    set(out ${BOLTNET_OUT}/keep_fig3b_${keep}_np${ranks})
    add_test(NAME keep_fig3b_${keep}_np${ranks}
      COMMAND ${BOLTNET_EXPECT} --match "30 steps converged \\(0 cut-backs\\)" --
              ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3b.yaml
              -output_dir ${out} -load_steps 30 -output_fields false -interface_keep_ratio ${keep})
    set_tests_properties(keep_fig3b_${keep}_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}"
      FIXTURES_SETUP keep_fig3b_${keep}_np${ranks})
  endforeach()
  set(on ${BOLTNET_OUT}/keep_fig3b_0.1_np${ranks})
  set(off ${BOLTNET_OUT}/keep_fig3b_0_np${ranks})
  add_test(NAME keep_fig3b_bearing_order_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fig3b.py ${on}/joints.csv 1,2,3,4)
  add_test(NAME keep_fig3b_same_joints_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${off}/joints.csv ${on}/joints.csv 1e-8)
  add_test(NAME keep_fig3b_fewer_factorisations_np${ranks}
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; on,off=(json.load(open(f)) for f in sys.argv[1:]); print('Jacobians assembled with and without the rule:', on['jacobians_assembled'], off['jacobians_assembled'], '; kept:', on['jacobians_kept'], off['jacobians_kept']); sys.exit(0 if on['jacobians_assembled'] < off['jacobians_assembled'] and on['jacobians_kept'] > 0 and off['jacobians_kept'] == 0 else 1)"
            ${on}/summary.json ${off}/summary.json)
  set_tests_properties(keep_fig3b_bearing_order_np${ranks} PROPERTIES FIXTURES_REQUIRED keep_fig3b_0.1_np${ranks})
  set_tests_properties(keep_fig3b_same_joints_np${ranks} keep_fig3b_fewer_factorisations_np${ranks}
    PROPERTIES FIXTURES_REQUIRED "keep_fig3b_0.1_np${ranks};keep_fig3b_0_np${ranks}")
endforeach()

# -info says where the rule keeps a factorisation, and by how much the residual fell there.
boltnet_expect(keep_info 1 --match "Jacobian and factorisation kept at iteration [1-9][0-9]* \\(residual [0-9.e+-]+ of the last\\)" --
  $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3b.yaml -output_dir ${BOLTNET_OUT}/keep_info
  -load_steps 30 -output_fields false -info :snes)

# Out of range: a ratio of 1 or more would keep a factorisation under which the residual grows.
foreach(bad -0.5 1 2)
  boltnet_expect(keep_ratio_bad_${bad} 1 --fail --max-lines 1 --match "-interface_keep_ratio ${bad}\\.? must be in .0, 1\\)" --
    $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/keep_ratio_bad
    -interface_keep_ratio ${bad})
endforeach()

# A run that keeps factorisations, killed after its checkpoint at step 1 and restarted, ends with the
# uninterrupted run's joints.csv to 1e-12 and the same Newton iterations step by step (check_restart.sh).
# Step 1, the first checkpoint: the 30 steps take well under a second, and a run killed after a later
# one had been seen to finish first on a busy machine. The 29 steps after the restart are compared:
# what is kept depends on the iterates of the current solve alone, not on what a process remembers.
# Without fields: the fields' restart is restart_killed_fig3a_* and restart_damaged_fields_fig3a_np2's
# subject, not this test's.
boltnet_expect(run_fig3b_keep 1 --match "30 steps converged"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3b.yaml -load_steps 30 -output_fields false -output_dir ${BOLTNET_OUT}/fig3b_keep_np1)
set_tests_properties(run_fig3b_keep_np1 PROPERTIES FIXTURES_SETUP fig3b_keep_np1)
add_test(NAME restart_killed_fig3b_keep_np1
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check_restart.sh ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver> 1 1 1
          ${BOLTNET_OUT}/fig3b_keep_np1 ${BOLTNET_OUT}/restart_fig3b_keep_np1 1e-12
          -- -scene ${BOLTNET_SCENES}/fig3b.yaml -load_steps 30 -output_fields false)
set_tests_properties(restart_killed_fig3b_keep_np1 PROPERTIES PROCESSORS 1 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED fig3b_keep_np1)
