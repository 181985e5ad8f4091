# The joint table joints.h5 (docs/output.md, "The joint table"). Included by CMakeLists.txt.
set(_table ${CMAKE_CURRENT_SOURCE_DIR}/check_joint_table.py)
set(_events ${CMAKE_CURRENT_SOURCE_DIR}/check_log_events.py)
set(_chain ${BOLTNET_TEST_SCENES}/chain.yaml)

# Requirement: joints.h5 holds what joints.csv holds (the rank-0 path, verified by the closed-form
# and rank tests: the independent reference) to the printed precision, on 1, 2 and 3 ranks. The
# chain: rigid patches only (no fields), all five states over 36 steps; lap-rows: shell patches,
# 20 joints.
foreach(ranks 1 2 3)
  boltnet_run(chain_table ${ranks} ${_chain} -output_joints both)
  boltnet_run(lap_rows_table ${ranks} ${BOLTNET_SCENES}/lap-rows.yaml -output_joints both -output_fields false)
  foreach(name chain_table lap_rows_table)
    add_test(NAME ${name}_vs_csv_np${ranks} COMMAND ${BOLTNET_PYTHON} ${_table} ${BOLTNET_OUT}/${name}_np${ranks})
    set_tests_properties(${name}_vs_csv_np${ranks} PROPERTIES FIXTURES_REQUIRED ${name}_np${ranks})
  endforeach()
endforeach()
# Requirement: rows do not depend on the number of ranks: 2 and 3 ranks write 1 rank's table (the
# tolerances of these scenes' joints.csv rank tests: chain 1e-10, lap-rows 1e-7).
foreach(ranks 2 3)
  add_test(NAME chain_table_ranks_1_vs_${ranks} COMMAND ${BOLTNET_PYTHON} ${_table} ${BOLTNET_OUT}/chain_table_np${ranks} --ref ${BOLTNET_OUT}/chain_table_np1 --rtol 1e-10)
  set_tests_properties(chain_table_ranks_1_vs_${ranks} PROPERTIES FIXTURES_REQUIRED "chain_table_np1;chain_table_np${ranks}")
  add_test(NAME lap_rows_table_ranks_1_vs_${ranks} COMMAND ${BOLTNET_PYTHON} ${_table} ${BOLTNET_OUT}/lap_rows_table_np${ranks} --ref ${BOLTNET_OUT}/lap_rows_table_np1 --rtol 1e-7)
  set_tests_properties(lap_rows_table_ranks_1_vs_${ranks} PROPERTIES FIXTURES_REQUIRED "lap_rows_table_np1;lap_rows_table_np${ranks}")
endforeach()
add_test(NAME odd_name_table COMMAND ${BOLTNET_PYTHON} ${_table} ${BOLTNET_OUT}/odd_name_np2)
set_tests_properties(odd_name_table PROPERTIES FIXTURES_REQUIRED odd_name_np2)

# Requirement: the default. auto (the default) writes joints.csv below -output_joints_auto_limit
# joints and joints.h5 alone from it on: the chain's 9 joints against a limit of 9, on 2 ranks, give
# the table of the run that wrote both, and no joints.csv.
boltnet_expect(joint_output_auto_table 2 --match "36 steps converged" --absent ${BOLTNET_OUT}/chain_auto_np2/joints.csv
  -- ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${_chain} -output_dir ${BOLTNET_OUT}/chain_auto_np2 -output_joints_auto_limit 9)
set_tests_properties(joint_output_auto_table_np2 PROPERTIES FIXTURES_SETUP chain_auto_np2)
add_test(NAME joint_output_auto_same_table COMMAND ${BOLTNET_PYTHON} ${_table} ${BOLTNET_OUT}/chain_auto_np2 --ref ${BOLTNET_OUT}/chain_table_np2 --rtol 0)
set_tests_properties(joint_output_auto_same_table PROPERTIES FIXTURES_REQUIRED "chain_auto_np2;chain_table_np2")
boltnet_expect(joint_output_auto_csv 1 --match "36 steps converged" --absent ${BOLTNET_OUT}/chain_auto_csv/joints.h5
  -- $<TARGET_FILE:boltnet_driver> -scene ${_chain} -output_dir ${BOLTNET_OUT}/chain_auto_csv -output_joints_auto_limit 10)

# Requirement: no rank gathers the joints for joints.h5. Every gather of joint records goes through
# GatherJointRecords, which counts PETSc event BoltnetJointGather: a run writing joints.h5 alone never
# enters it (while its joint output, BoltnetJointOutput, runs each step); the csv run, the control,
# does, so the check can fail.
foreach(mode hdf5 csv)
  if(mode STREQUAL "hdf5")
    set(_expect BoltnetJointGather=0 BoltnetJointOutput=36)
  else()
    set(_expect BoltnetJointGather=36 BoltnetJointOutput=36)
  endif()
  add_test(NAME joint_output_gathers_${mode}_np3
    COMMAND sh -c "rm -rf \"$3\" && \"$0\" -n 3 --oversubscribe \"$1\" -scene \"$2\" -output_dir \"$3\" -output_joints $4 -log_view :\"$3.log\" > /dev/null && \"$5\" \"$6\" \"$3.log\" $7 $8"
            ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver> ${_chain} ${BOLTNET_OUT}/chain_gathers_${mode} ${mode} ${BOLTNET_PYTHON} ${_events} ${_expect})
  set_tests_properties(joint_output_gathers_${mode}_np3 PROPERTIES PROCESSORS 3 ENVIRONMENT "${BOLTNET_ENV}")
endforeach()

# Requirement: a plot script reads the table. plot_joints.py draws the same data (x, y, states of
# every joint, written by --data) from joints.h5 as from joints.csv of the same run.
foreach(chart load force)
  set(_flag "")
  if(chart STREQUAL "force")
    set(_flag --force)
  endif()
  add_test(NAME plot_joints_table_${chart}
    COMMAND sh -c "\"$0\" \"$1\" \"$2/joints.csv\" -o \"$2/plot-csv-$3.png\" --data \"$2/plot-csv-$3.json\" $4 && \"$0\" \"$1\" \"$2/joints.h5\" -o \"$2/plot-h5-$3.png\" --data \"$2/plot-h5-$3.json\" $4 && cmp \"$2/plot-csv-$3.json\" \"$2/plot-h5-$3.json\" && echo 'the same chart data'"
            ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/plot_joints.py ${BOLTNET_OUT}/chain_table_np2 ${chart} ${_flag})
  set_tests_properties(plot_joints_table_${chart} PROPERTIES FIXTURES_REQUIRED chain_table_np2)
endforeach()

# Requirement: restart. A run writing joints.h5 alone, killed with SIGKILL on 2 ranks after its first
# checkpoint (later steps may be in the table already: the restart cuts them) and continued on 3,
# ends with the table of an uninterrupted run (chain rank tolerance 1e-10).
boltnet_expect(run_chain_long_table 2 --match "150 steps converged"
  -- ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${_chain} -load_steps 50 -output_joints hdf5 -output_dir ${BOLTNET_OUT}/chain_long_table_np2)
set_tests_properties(run_chain_long_table_np2 PROPERTIES FIXTURES_SETUP chain_long_table_np2)
add_test(NAME restart_killed_chain_table_np2_to_np3
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check_restart.sh ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver> 2 3 10 ${BOLTNET_OUT}/chain_long_table_np2 ${BOLTNET_OUT}/restart_chain_table 1e-10
          -- -scene ${_chain} -load_steps 50 -output_joints hdf5)
set_tests_properties(restart_killed_chain_table_np2_to_np3 PROPERTIES PROCESSORS 3 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED chain_long_table_np2)
# The same with joints.h5 left shorter than its superblock records, as a kill while HDF5 extended it
# can leave it (damage_fields.py --short): rank 0 extends it before the 3 ranks of the restart open it.
add_test(NAME restart_short_chain_table_np2_to_np3
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check_restart.sh ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver> 2 3 10 ${BOLTNET_OUT}/chain_long_table_np2 ${BOLTNET_OUT}/restart_short_chain_table 1e-10
          --short joints.h5 -- -scene ${_chain} -load_steps 50 -output_joints hdf5)
set_tests_properties(restart_short_chain_table_np2_to_np3 PROPERTIES PROCESSORS 3 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED chain_long_table_np2)
# Both files, written on 3 ranks and continued on 1 from the last checkpoint (step 20 of 36): the
# restart first refuses while joints.h5 is missing (naming it; joints.csv left as it was), then
# continues both, which still agree with each other and with the uninterrupted run's table.
add_test(NAME restart_chain_table_both_np3_to_np1
  COMMAND sh -c "rm -rf \"$3\" && \"$0\" -n 3 --oversubscribe \"$1\" -scene \"$2\" -output_joints both -checkpoint_every 20 -output_dir \"$3\" > /dev/null && mv \"$3/joints.h5\" \"$3/joints.h5.away\" && \"$4\" --fail --max-lines 2 --unchanged \"$3/joints.csv\" --match \"Cannot restart: there is no readable joint table .*joints.h5 to continue\" -- \"$1\" -scene \"$2\" -output_joints both -output_dir \"$3\" -restart \"$3/checkpoint.h5\" && mv \"$3/joints.h5.away\" \"$3/joints.h5\" && \"$4\" --match \"restart from .* at step 20\" -- \"$1\" -scene \"$2\" -output_joints both -output_dir \"$3\" -restart \"$3/checkpoint.h5\" && \"$5\" \"$6\" \"$3\" && \"$5\" \"$6\" \"$3\" --ref \"$7\" --rtol 1e-10"
          ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver> ${_chain} ${BOLTNET_OUT}/restart_chain_both ${BOLTNET_EXPECT} ${BOLTNET_PYTHON} ${_table} ${BOLTNET_OUT}/chain_table_np1)
set_tests_properties(restart_chain_table_both_np3_to_np1 PROPERTIES PROCESSORS 3 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED chain_table_np1)
# A table whose last row names a joint the model does not have is refused before anything changes:
# on 3 ranks only the last rank reads that row, and every rank stops with its reason.
add_test(NAME restart_table_other_joint_np3
  COMMAND sh -c "rm -rf \"$3\" && \"$0\" -n 3 --oversubscribe \"$1\" -scene \"$2\" -output_joints hdf5 -checkpoint_every 20 -output_dir \"$3\" > /dev/null && \"$5\" \"$6\" \"$3/joints.h5\" && \"$4\" --fail --max-lines 2 --unchanged \"$3/joints.h5\" --match \"Cannot restart: .*joints.h5 is not the joint table of the run that wrote the checkpoint: its joints are not the model's\" -- \"$0\" -n 3 --oversubscribe --quiet \"$1\" -scene \"$2\" -output_joints hdf5 -output_dir \"$3\" -restart \"$3/checkpoint.h5\""
          ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver> ${_chain} ${BOLTNET_OUT}/restart_table_other_joint ${BOLTNET_EXPECT} ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/renumber_table_joint.py)
set_tests_properties(restart_table_other_joint_np3 PROPERTIES PROCESSORS 3 ENVIRONMENT "${BOLTNET_ENV}")
# Another -output_joints than the checkpoint's run is refused (its files could not be continued).
boltnet_expect(restart_refuses_other_joint_output 1 --fail --max-lines 2 --unchanged ${BOLTNET_OUT}/ckpt_fig3c/joints.csv
  --match "other options that change results: -output_joints hdf5 \\(checkpoint: not given\\)"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -load_steps 5 -output_dir ${BOLTNET_OUT}/ckpt_fig3c -output_joints hdf5 -restart ${BOLTNET_OUT}/ckpt_fig3c/checkpoint.h5)
set_tests_properties(restart_refuses_other_joint_output_np1 PROPERTIES FIXTURES_REQUIRED ckpt_fig3c)

# Bad input: each names the file or option, in one line, exits non-zero.
# An output directory that cannot be written leaves an earlier run's files as they were (run as an
# unprivileged user: root writes anywhere; skipped where that is not possible).
add_test(NAME joint_output_unwritable_dir
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check_unwritable_output.sh $<TARGET_FILE:boltnet_driver> ${BOLTNET_OUT}/unwritable ${BOLTNET_EXPECT} -- -scene ${_chain} -output_joints both)
set_tests_properties(joint_output_unwritable_dir PROPERTIES SKIP_RETURN_CODE 77 ENVIRONMENT "${BOLTNET_ENV}")
# A file in the place of the output directory.
add_test(NAME joint_output_dir_is_file
  COMMAND sh -c "rm -rf \"$1\" && mkdir -p \"$1\" && echo keep > \"$1/file\" && \"$2\" --fail --max-lines 1 --unchanged \"$1/file\" --match \"Cannot write results in the output directory '.*file/out' \\(-output_dir\\)\" -- \"$0\" -scene \"$3\" -output_joints hdf5 -output_dir \"$1/file/out\""
          $<TARGET_FILE:boltnet_driver> ${BOLTNET_OUT}/dir_is_file ${BOLTNET_EXPECT} ${_chain})
set_tests_properties(joint_output_dir_is_file PROPERTIES ENVIRONMENT "${BOLTNET_ENV}")
# joints.h5 cannot be created (a directory is in its way), on 2 ranks: every rank stops with the file
# and HDF5's reason.
add_test(NAME joint_table_cannot_create_np2
  COMMAND sh -c "rm -rf \"$2\" && mkdir -p \"$2/joints.h5/x\" && \"$3\" --fail --max-lines 2 --match \"Cannot write the joint table .*joints.h5 \\(-output_joints\\): \" -- \"$0\" -n 2 --oversubscribe --quiet \"$1\" -scene \"$4\" -output_joints hdf5 -output_dir \"$2\""
          ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver> ${BOLTNET_OUT}/table_in_way ${BOLTNET_EXPECT} ${_chain})
set_tests_properties(joint_table_cannot_create_np2 PROPERTIES PROCESSORS 2 ENVIRONMENT "${BOLTNET_ENV}")
boltnet_expect(joint_output_bad_mode 1 --fail --max-lines 2 --match "-output_joints"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_chain} -output_dir ${BOLTNET_OUT}/bad -output_joints xml)
boltnet_expect(joint_output_bad_limit 1 --fail --max-lines 1 --match "-output_joints_auto_limit -1: a number of joints must be >= 0"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_chain} -output_dir ${BOLTNET_OUT}/bad -output_joints_auto_limit -1)
