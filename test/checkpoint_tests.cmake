# Checkpoint and restart (docs/scenes.md, "Checkpoint and restart"). Included by CMakeLists.txt.
set(_restart ${CMAKE_CURRENT_SOURCE_DIR}/check_restart.sh ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver>)

# A night's run survives a killed job: fig3a (condensed shell patches, fields) killed with SIGKILL as
# soon as the checkpoint of step 10 is on disk, then restarted, ends with the joints.csv of the run
# that was not interrupted (run_fig3a_np*) to 1e-12 of each quantity's scale, the same record of the
# steps in summary.json, and the same fields. On 1 rank the runs are identical to the bit (measured:
# 0). On 2 ranks two uninterrupted runs already differ (MUMPS's parallel factorisation): by 7e-14 in
# joints.csv and 4.7e-12 in the fields (measured), so the fields are compared to 1e-10 there.
add_test(NAME restart_killed_fig3a_np1
  COMMAND ${_restart} 1 1 10 ${BOLTNET_OUT}/fig3a_np1 ${BOLTNET_OUT}/restart_fig3a_np1 1e-12
          --fields ${BOLTNET_SCENES}/fig3a.joints.csv 1e-12 -- -scene ${BOLTNET_SCENES}/fig3a.yaml)
add_test(NAME restart_killed_fig3a_np2
  COMMAND ${_restart} 2 2 10 ${BOLTNET_OUT}/fig3a_np2 ${BOLTNET_OUT}/restart_fig3a_np2 1e-12
          --fields ${BOLTNET_SCENES}/fig3a.joints.csv 1e-10 -- -scene ${BOLTNET_SCENES}/fig3a.yaml)
set_tests_properties(restart_killed_fig3a_np1 PROPERTIES PROCESSORS 1 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED fig3a_np1)
set_tests_properties(restart_killed_fig3a_np2 PROPERTIES PROCESSORS 2 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED fig3a_np2)
# A kill while HDF5 extends fields.h5 can leave the file shorter than the end its superblock records
# (HDF5 then refuses all of it: "truncated file"; measured on this test's killed run, 328 bytes
# short): the same kill, fields.h5 then left short (damage_fields.py --short), and the restart extends it
# (ExtendShortHDF5) and ends as restart_killed_fig3a_np2. Before, the restart stopped, unable to open
# fields.h5.
add_test(NAME restart_short_fields_fig3a_np2
  COMMAND ${_restart} 2 2 10 ${BOLTNET_OUT}/fig3a_np2 ${BOLTNET_OUT}/restart_short_fig3a_np2 1e-12
          --fields ${BOLTNET_SCENES}/fig3a.joints.csv 1e-10 --short fields.h5 -- -scene ${BOLTNET_SCENES}/fig3a.yaml)
set_tests_properties(restart_short_fields_fig3a_np2 PROPERTIES PROCESSORS 2 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED fig3a_np2)

# A kill while HDF5 writes a step's fields can leave that step's group unreadable and unremovable
# ("link count would be negative", "bad object header version number"): fig3a on 2 ranks with a
# checkpoint every 40 steps runs to its end (the last checkpoint at step 80, fields up to 90), step 81
# of fields.h5 is damaged (damage_fields.py), and the restart from step 80 rebuilds fields.h5 from
# steps 1 to 80 and ends with the uninterrupted run's joints.csv (1e-12) and fields (1e-10, as
# restart_killed_fig3a_np2). Before the rebuild the restart stopped on the damaged step (exit 1). The
# restart also turns -output_stresses_cache off, which only trades memory for time and so may change.
add_test(NAME restart_damaged_fields_fig3a_np2
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check_restart_damaged_fields.sh ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver> 2 40
          ${BOLTNET_OUT}/fig3a_np2 ${BOLTNET_OUT}/restart_damaged_fig3a_np2 ${BOLTNET_SCENES}/fig3a.joints.csv
          -- -scene ${BOLTNET_SCENES}/fig3a.yaml)
set_tests_properties(restart_damaged_fields_fig3a_np2 PROPERTIES PROCESSORS 2 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED fig3a_np2)

# The secant predictor's other point survives a restart (docs/solver.md, "The first iterate of a
# step"): fig3c in 2,000 steps per segment, whose steps 3,001 to 4,000 take one Newton iteration from
# the prediction and two without, killed after step 3,100 (its only checkpoint; 2,900 steps, over a
# second, are left for the kill to land) and restarted, repeats the uninterrupted run's Newton
# iterations step by step. A restart that lost the point starts step 3,101 from the converged
# solution alone and records 2 (measured: the test then fails).
boltnet_expect(run_fig3c_long 1 --match "6000 steps converged"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -load_steps 2000 -output_dir ${BOLTNET_OUT}/fig3c_long_np1)
set_tests_properties(run_fig3c_long_np1 PROPERTIES FIXTURES_SETUP fig3c_long_np1)
add_test(NAME restart_killed_fig3c_np1
  COMMAND ${_restart} 1 1 3100 ${BOLTNET_OUT}/fig3c_long_np1 ${BOLTNET_OUT}/restart_fig3c_np1 1e-12
          -- -scene ${BOLTNET_SCENES}/fig3c.yaml -load_steps 2000)
set_tests_properties(restart_killed_fig3c_np1 PROPERTIES PROCESSORS 1 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED fig3c_long_np1)
# Another number of ranks: the checkpoint's arrays do not depend on the ranks, so a run of the chain
# killed on 2 ranks goes on on 3 and ends with the uninterrupted 2-rank run's results to the rank
# tolerance of the chain (1e-10, as chain_ranks_1_vs_*). 150 steps: the kill comes long before the end.
# (The reference runs without boltnet_run's -malloc_debug, which makes its 150 steps ten times slower.)
boltnet_expect(run_chain_long 2 --match "150 steps converged"
  -- ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/chain.yaml -load_steps 50 -output_dir ${BOLTNET_OUT}/chain_long_np2)
set_tests_properties(run_chain_long_np2 PROPERTIES FIXTURES_SETUP chain_long_np2)
add_test(NAME restart_killed_chain_np2_to_np3
  COMMAND ${_restart} 2 3 10 ${BOLTNET_OUT}/chain_long_np2 ${BOLTNET_OUT}/restart_chain 1e-10
          -- -scene ${BOLTNET_TEST_SCENES}/chain.yaml -load_steps 50)
set_tests_properties(restart_killed_chain_np2_to_np3 PROPERTIES PROCESSORS 3 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED chain_long_np2)
# And the other way: written on 3 ranks (the last checkpoint at step 120 of 150; the run goes on to
# the end), continued on 1 from step 120 in the same directory, against the same reference.
add_test(NAME restart_chain_np3_to_np1
  COMMAND sh -c "rm -rf \"$3\" && \"$0\" -n 3 --oversubscribe \"$1\" -scene \"$2\" -load_steps 50 -checkpoint_every 40 -output_dir \"$3\" > \"$3.log\" 2>&1 && \"$0\" -n 1 \"$1\" -scene \"$2\" -load_steps 50 -restart \"$3/checkpoint.h5\" -output_dir \"$3\" >> \"$3.log\" 2>&1 && grep -q 'restart from .* at step 120' \"$3.log\" && ${BOLTNET_PYTHON} \"$4\" \"$5/joints.csv\" \"$3/joints.csv\" 1e-10"
          ${MPIEXEC_EXECUTABLE} $<TARGET_FILE:boltnet_driver> ${BOLTNET_TEST_SCENES}/chain.yaml ${BOLTNET_OUT}/restart_chain_np3
          ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/chain_long_np2)
set_tests_properties(restart_chain_np3_to_np1 PROPERTIES PROCESSORS 3 ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED chain_long_np2)

# The load path's position between cut-backs: fig3a with a mechanism at 450 N (kc = 0, as
# trust_mechanism_named) fails after 8 halvings; its last checkpoint lies between two of them, and the
# restart fails at the same step after the same halvings, with the same joints.csv and message.
add_test(NAME restart_between_cutbacks
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check_restart_failed.sh $<TARGET_FILE:boltnet_driver> ${BOLTNET_OUT}/restart_cutbacks
          -- -scene ${BOLTNET_SCENES}/fig3a.yaml -joint_bolt_kc 0)
set_tests_properties(restart_between_cutbacks PROPERTIES ENVIRONMENT "${BOLTNET_ENV}")

# Refusals: each names what differs, in one line, exits non-zero and leaves the results of the run
# that wrote the checkpoint (and the checkpoint) as they were. The checkpoints: fig3c at step 15 (1
# rank) and fig3a at step 6 (2 ranks, its plates cut into patches by the rank count).
set(_c3 ${BOLTNET_OUT}/ckpt_fig3c)
boltnet_expect(checkpoint_fig3c 1 --match "15 steps converged"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -load_steps 5 -checkpoint_every 5 -output_dir ${_c3})
set_tests_properties(checkpoint_fig3c_np1 PROPERTIES FIXTURES_SETUP ckpt_fig3c)
set(_c3a ${BOLTNET_OUT}/ckpt_fig3a)
boltnet_expect(checkpoint_fig3a 2 --match "6 steps converged"
  -- ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml -load_steps 2 -checkpoint_every 3 -output_dir ${_c3a})
set_tests_properties(checkpoint_fig3a_np2 PROPERTIES FIXTURES_SETUP ckpt_fig3a)
add_test(NAME checkpoint_damaged_copies COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/damage_checkpoint.py ${_c3}/checkpoint.h5 ${BOLTNET_OUT}/ckpt_damaged)
set_tests_properties(checkpoint_damaged_copies PROPERTIES FIXTURES_REQUIRED ckpt_fig3c FIXTURES_SETUP ckpt_damaged)

set(_keep --fail --max-lines 2 --unchanged ${_c3}/joints.csv --unchanged ${_c3}/checkpoint.h5)
set(_fig3c $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${_c3})
boltnet_expect(restart_refuses_other_scene 1 ${_keep} --match "checkpoint .*ckpt_fig3c/checkpoint.h5 \\(-restart\\) is of scene 'fig3c', this run is scene 'chain'"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/chain.yaml -output_dir ${_c3} -restart ${_c3}/checkpoint.h5)
boltnet_expect(restart_refuses_changed_option 1 ${_keep} --match "written with other options that change results: -joint_bolt_mu 0.2 \\(checkpoint: 0.3\\)"
  -- ${_fig3c} -load_steps 5 -joint_bolt_mu 0.2 -restart ${_c3}/checkpoint.h5)
boltnet_expect(restart_refuses_other_path 1 ${_keep} --match "other options that change results: -load_steps 60 \\(checkpoint: 5\\)"
  -- ${_fig3c} -restart ${_c3}/checkpoint.h5)
boltnet_expect(restart_refuses_solver_option 1 ${_keep} --match "other options that change results: -snes_linesearch_type basic \\(checkpoint: not given\\)"
  -- ${_fig3c} -load_steps 5 -snes_linesearch_type basic -restart ${_c3}/checkpoint.h5)
# Options that only choose what is printed or written may differ.
boltnet_expect(restart_takes_print_options 1 --match "restart from .*checkpoint.h5 at step 15" --match "15 steps converged"
  --unchanged ${BOLTNET_OUT}/ckpt_fig3c_again/joints.csv
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -load_steps 5 -output_dir ${BOLTNET_OUT}/ckpt_fig3c_again
     -restart ${BOLTNET_OUT}/ckpt_fig3c_again/checkpoint.h5 -joint_monitor -snes_converged_reason -output_fields false)
set_tests_properties(restart_takes_print_options_np1 PROPERTIES FIXTURES_REQUIRED ckpt_fig3c_again)
boltnet_expect(checkpoint_fig3c_again 1 --match "15 steps converged"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -load_steps 5 -checkpoint_every 5 -output_dir ${BOLTNET_OUT}/ckpt_fig3c_again)
set_tests_properties(checkpoint_fig3c_again_np1 PROPERTIES FIXTURES_SETUP ckpt_fig3c_again)
# The model: a copy of fig3c whose boundary table changes after the checkpoint (no option changes).
add_test(NAME restart_refuses_changed_model
  COMMAND sh -c "rm -rf \"$2\" && mkdir -p \"$2\" && cp \"$1\"/fig3c.* \"$2\"/ && \"$0\" -scene \"$2/fig3c.yaml\" -load_steps 2 -checkpoint_every 2 -output_dir \"$2/out\" > /dev/null && sed -i 's/^1,ux,force,1$/1,ux,force,2/' \"$2/fig3c.bcs.csv\" && \"$3\" --fail --max-lines 2 --unchanged \"$2/out/joints.csv\" --match \"was written for another model: the boundary conditions of this scene differ\" -- \"$0\" -scene \"$2/fig3c.yaml\" -load_steps 2 -output_dir \"$2/out\" -restart \"$2/out/checkpoint.h5\""
          $<TARGET_FILE:boltnet_driver> ${BOLTNET_SCENES} ${BOLTNET_OUT}/ckpt_model ${BOLTNET_EXPECT})
set_tests_properties(restart_refuses_changed_model PROPERTIES ENVIRONMENT "${BOLTNET_ENV}")
# fields.h5 left unreadable (a kill while HDF5 writes a step): refused, naming the way on without
# fields, which then works.
add_test(NAME restart_refuses_damaged_fields
  COMMAND sh -c "rm -rf \"$1\" && \"$0\" -scene \"$2\" -load_steps 2 -checkpoint_every 3 -output_dir \"$1\" > /dev/null && truncate -s 20000 \"$1/fields.h5\" && \"$3\" --fail --max-lines 2 --unchanged \"$1/joints.csv\" --match \"Cannot continue the fields in .*fields.h5: .*\\(-output_fields false restarts without fields\\)\" -- \"$0\" -scene \"$2\" -load_steps 2 -output_dir \"$1\" -restart \"$1/checkpoint.h5\" && \"$3\" --match \"restart from .* at step 6\" --match \"6 steps converged\" -- \"$0\" -scene \"$2\" -load_steps 2 -output_dir \"$1\" -restart \"$1/checkpoint.h5\" -output_fields false"
          $<TARGET_FILE:boltnet_driver> ${BOLTNET_OUT}/ckpt_fields ${BOLTNET_SCENES}/fig3a.yaml ${BOLTNET_EXPECT})
set_tests_properties(restart_refuses_damaged_fields PROPERTIES ENVIRONMENT "${BOLTNET_ENV}")
# Another rank count on a network laid out by the rank count (-patch_max_nodes -1, fig3a's plates cut
# into patches on 2 ranks, whole on 1): refused, naming both counts.
boltnet_expect(restart_refuses_other_layout 1 --fail --max-lines 2 --unchanged ${_c3a}/joints.csv
  --match "written on 2 rank\\(s\\), this run has 1, and the network is laid out differently on them"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml -load_steps 2 -output_dir ${_c3a} -restart ${_c3a}/checkpoint.h5)
# Damaged files: cut short (HDF5 cannot open it), a value of the solution changed (the arrays'
# checksum), a scalar changed (the scalars' checksum); a file that is not a checkpoint; no file.
set(_dmg ${BOLTNET_OUT}/ckpt_damaged)
boltnet_expect(restart_refuses_truncated 1 ${_keep} --match "Cannot read the checkpoint .*truncated.h5 \\(-restart\\): it is damaged, cut short or not a checkpoint"
  -- ${_fig3c} -load_steps 5 -restart ${_dmg}/truncated.h5)
boltnet_expect(restart_refuses_changed_data 1 ${_keep} --match "checkpoint .*data.h5 \\(-restart\\) is damaged: its arrays do not match their checksum"
  -- ${_fig3c} -load_steps 5 -restart ${_dmg}/data.h5)
boltnet_expect(restart_refuses_changed_scalar 1 ${_keep} --match "checkpoint .*scalars.h5 \\(-restart\\) is damaged: its scalars do not match their checksum"
  -- ${_fig3c} -load_steps 5 -restart ${_dmg}/scalars.h5)
set_tests_properties(restart_refuses_truncated_np1 restart_refuses_changed_data_np1 restart_refuses_changed_scalar_np1 PROPERTIES FIXTURES_REQUIRED "ckpt_fig3c;ckpt_damaged")
boltnet_expect(restart_refuses_not_checkpoint 1 ${_keep} --match "ckpt_fig3a/fields.h5 \\(-restart\\) is an HDF5 file but not a boltnet checkpoint"
  -- ${_fig3c} -load_steps 5 -restart ${_c3a}/fields.h5)
boltnet_expect(restart_refuses_missing_file 1 ${_keep} --match "No checkpoint file .*no-such.h5 \\(-restart\\)"
  -- ${_fig3c} -load_steps 5 -restart ${BOLTNET_OUT}/no-such.h5)
set_tests_properties(restart_refuses_other_scene_np1 restart_refuses_changed_option_np1 restart_refuses_other_path_np1
  restart_refuses_solver_option_np1 restart_refuses_missing_file_np1 PROPERTIES FIXTURES_REQUIRED ckpt_fig3c)
set_tests_properties(restart_refuses_not_checkpoint_np1 PROPERTIES FIXTURES_REQUIRED "ckpt_fig3c;ckpt_fig3a")
set_tests_properties(restart_refuses_other_layout_np1 PROPERTIES FIXTURES_REQUIRED ckpt_fig3a)
# The results it continues must be the checkpoint's run's: another output directory is refused.
boltnet_expect(restart_refuses_other_output_dir 1 --fail --max-lines 2 --match "Cannot restart: there is no .*ckpt_elsewhere/joints.csv to continue"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -load_steps 5 -output_dir ${BOLTNET_OUT}/ckpt_elsewhere -restart ${_c3}/checkpoint.h5)
set_tests_properties(restart_refuses_other_output_dir_np1 PROPERTIES FIXTURES_REQUIRED ckpt_fig3c)
# A checkpoint that could not be written is named before the run starts, not hours into it.
boltnet_expect(checkpoint_file_no_directory 1 --fail --max-lines 1 --unchanged ${BOLTNET_OUT}/bad/joints.csv
  --match "Cannot write the checkpoint .*no-such-dir/c.h5 \\(-checkpoint_file\\): its directory '.*no-such-dir' does not exist"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -checkpoint_every 5
     -checkpoint_file ${BOLTNET_OUT}/no-such-dir/c.h5)
boltnet_expect(checkpoint_every_negative 1 --fail --max-lines 1 --match "-checkpoint_every -1 must be >= 0"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -checkpoint_every -1)
boltnet_expect(checkpoint_help 1 --match "-checkpoint_every <now 0 : formerly 0>: Write a checkpoint" --match "-restart <now  : formerly >: Go on from this checkpoint"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -help -output_dir ${BOLTNET_OUT}/help)

# With the lagged interface solve chosen by -interface_solve auto (the threshold at 1 flop per
# entry, so that fig3a's small interface qualifies), the joints are the direct solve's to 1e-8, with
# Eisenstat-Walker's tolerances (the lagged solve's default) and the same steps. A restarted run
# makes the choice again from its own first analysis and factors afresh at the restart step, where
# the uninterrupted run kept an earlier factorisation: its joints agree to GMRES's tolerance, not
# to the bit (measured 7.4e-14 of each quantity's scale), with the same record of the steps when
# GMRES solves to 1e-12 (-snes_ksp_ew false -ksp_rtol 1e-12, both runs). With Eisenstat-Walker's
# tolerances a direction depends on the preconditioner GMRES had, so a restart may take other
# Newton paths (docs/solver.md, "Inexact Newton"): the record is compared where the solves are
# exact. 1e-10 is not exact enough for that: at fig3a's step 87 (initial residual 63 N, the step's
# absolute tolerance 3e-9 N) GMRES may stop anywhere below 6.3e-9 N, and whether its last iterate
# lands above or below 3e-9 N, and so whether Newton takes a second iteration, then depends on the
# round-off of the 3-rank factorisation (a full run under load once took two there). At 1e-12 of
# the initial residual every stop after the checkpoint lies below 0.56 of its step's tolerance (the
# largest: step 48, where the load turns, 1.7e-9 N against 3e-9 N).
# On 2 ranks the run killed at step 10 is restarted on 3, whose analysis makes the choice again.
foreach(ranks 1 2)
  if(ranks EQUAL 1)
    set(restart_ranks 1)
  else()
    math(EXPR restart_ranks "${ranks} + 1")
  endif()
  boltnet_run(fig3a_auto_lagged ${ranks} ${BOLTNET_SCENES}/fig3a.yaml -interface_lagged_flops_per_entry 1)
  add_test(NAME fig3a_auto_lagged_same_as_direct_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/fig3a_np${ranks}/joints.csv ${BOLTNET_OUT}/fig3a_auto_lagged_np${ranks}/joints.csv 1e-8)
  set_tests_properties(fig3a_auto_lagged_same_as_direct_np${ranks} PROPERTIES FIXTURES_REQUIRED "fig3a_np${ranks};fig3a_auto_lagged_np${ranks}")
  add_test(NAME fig3a_auto_lagged_ksp_ew_np${ranks}
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['interface_solve'], 'ksp_ew', s['ksp_ew'], 'cutbacks', s['cutbacks']); sys.exit(0 if s['interface_solve'] == 'lagged' and s['ksp_ew'] and s['cutbacks'] == 0 else 1)"
            ${BOLTNET_OUT}/fig3a_auto_lagged_np${ranks}/summary.json)
  set_tests_properties(fig3a_auto_lagged_ksp_ew_np${ranks} PROPERTIES FIXTURES_REQUIRED fig3a_auto_lagged_np${ranks})
  boltnet_run(fig3a_auto_lagged_exact ${ranks} ${BOLTNET_SCENES}/fig3a.yaml -interface_lagged_flops_per_entry 1 -snes_ksp_ew false -ksp_rtol 1e-12)
  add_test(NAME restart_killed_fig3a_auto_lagged_np${ranks}
    COMMAND ${_restart} ${ranks} ${restart_ranks} 10 ${BOLTNET_OUT}/fig3a_auto_lagged_exact_np${ranks} ${BOLTNET_OUT}/restart_fig3a_auto_lagged_np${ranks} 1e-8
            -- -scene ${BOLTNET_SCENES}/fig3a.yaml -interface_lagged_flops_per_entry 1 -snes_ksp_ew false -ksp_rtol 1e-12)
  set_tests_properties(restart_killed_fig3a_auto_lagged_np${ranks} PROPERTIES PROCESSORS ${restart_ranks} ENVIRONMENT "${BOLTNET_ENV}"
    FIXTURES_REQUIRED fig3a_auto_lagged_exact_np${ranks} FIXTURES_SETUP restart_fig3a_auto_lagged_np${ranks})
  add_test(NAME restart_fig3a_auto_lagged_is_lagged_np${ranks}
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['interface_solve'], s['lagged_factorisations']); sys.exit(0 if s['interface_solve'] == 'lagged' and s['lagged_factorisations'] >= 1 else 1)"
            ${BOLTNET_OUT}/restart_fig3a_auto_lagged_np${ranks}/summary.json)
  set_tests_properties(restart_fig3a_auto_lagged_is_lagged_np${ranks} PROPERTIES FIXTURES_REQUIRED restart_fig3a_auto_lagged_np${ranks})
endforeach()
