# Resident memory per rank (summary.json's memory_mb, the driver's peak line; docs/performance.md,
# "Memory per rank") against the operating system's own count of the run's largest process, read by
# check_memory.py as the parent of mpiexec.
foreach(ranks 1 2 3)
  set(out ${BOLTNET_OUT}/memory_lap_rows_np${ranks})
  add_test(NAME memory_report_lap_rows_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_memory.py ${out}
            ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml
            -output_dir ${out} -output_fields false)
  set_tests_properties(memory_report_lap_rows_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}")
endforeach()

# A factorisation that fails for want of memory is not cut back (the matrix, and the memory it
# needs, is the same at any load): the same step is factored again once with the factors on disk
# (-interface_out_of_core, the default), and if that fails too the run stops saying why (exit 3,
# summary.json "failed" with MUMPS's INFOG(1)). The references are MUMPS's own diagnoses and, where
# the run converges, lap-rows' closed-form load shares. -mat_mumps_icntl_23 caps MUMPS's working
# memory per rank: lap-rows' 26,472 dof need 37 to 55 MB per rank in core and 19 to 25 MB out of
# core on 1 to 3 ranks (MUMPS's INFOG(16), INFOG(26)); no factorisation fits in 1 MB.
foreach(ranks 1 2 3)
  set(out ${BOLTNET_OUT}/factor_memory_cap_np${ranks})
  boltnet_expect(factor_memory_cap ${ranks} --status 3
    --match "load step 1: MUMPS could not factor the 26472-dof Jacobian \\(INFOG\\(1\\) = -19.*factoring again with the factors on disk"
    --match "FAILED: Load step 1 from load factor 0 to 1: MUMPS could not factor the 26472-dof Jacobian with its factors on disk \\(INFOG\\(1\\) = -19"
    --match "mat_mumps_icntl_23 caps"
    --reject "cutting the increment" --
    ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml
    -output_dir ${out} -output_fields false -patch_condense false -mat_mumps_icntl_23 1)
  add_test(NAME factor_memory_cap_summary_np${ranks}
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); sys.exit(0 if s['status']=='failed' and 'INFOG(1) = -19' in s['message'] and s['cutbacks']==0 and s['factors_on_disk'] else 'summary.json: ' + s['status'] + ', ' + s['message'])" ${out}/summary.json)
  set_tests_properties(factor_memory_cap_summary_np${ranks} PROPERTIES DEPENDS factor_memory_cap_np${ranks})
  # A 30 MB cap: in core does not fit, on disk does; the run converges to the load shares.
  set(out ${BOLTNET_OUT}/factor_out_of_core_np${ranks})
  add_test(NAME factor_out_of_core_np${ranks}
    COMMAND ${BOLTNET_EXPECT} --match "factoring again with the factors on disk" --match "1 steps converged \\(0 cut-backs\\)" --
            ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml
            -output_dir ${out} -output_fields false -patch_condense false -mat_mumps_icntl_23 30)
  set_tests_properties(factor_out_of_core_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_SETUP factor_out_of_core_np${ranks})
  add_test(NAME factor_out_of_core_load_shares_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_lap_rows.py ${out}/joints.csv 21820 72000 20 1.27 20)
  set_tests_properties(factor_out_of_core_load_shares_np${ranks} PROPERTIES FIXTURES_REQUIRED factor_out_of_core_np${ranks})
endforeach()
# A lagged solve that -interface_solve auto chose in core (the threshold at 1 flop per entry) turns
# direct again when the factorisation runs out of memory and the factors go to disk, below auto's
# threshold for factors on disk (docs/solver.md, "Which one the default takes"), and stays lagged
# with that threshold at 1 too; either retry converges to the closed-form load shares.
foreach(ranks 1 2 3)
  foreach(case direct lagged)
    set(out ${BOLTNET_OUT}/factor_out_of_core_auto_${case}_np${ranks})
    if(case STREQUAL "direct")
      set(extra --match "factoring again with the factors on disk" --match "the interface solve is direct again, as -interface_solve auto chooses with factors on disk \\(-interface_lagged_flops_per_entry_on_disk\\)")
      set(opts "")
      set(name factor_out_of_core_auto_lagged_np${ranks})
    else()
      set(extra --match "factoring again with the factors on disk" --reject "direct again")
      set(opts -interface_lagged_flops_per_entry_on_disk 1)
      set(name factor_out_of_core_auto_stays_lagged_np${ranks})
    endif()
    add_test(NAME ${name}
      COMMAND ${BOLTNET_EXPECT} --match "the interface solve is lagged" ${extra}
              --match "1 steps converged \\(0 cut-backs\\)" -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver>
              -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${out} -output_fields false -patch_condense false -mat_mumps_icntl_23 30
              -interface_lagged_flops_per_entry 1 ${opts} -malloc_debug -malloc_dump)
    set_tests_properties(${name} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}"
      FIXTURES_SETUP ${name} FAIL_REGULAR_EXPRESSION "PETSC ERROR;bytes [A-Za-z_0-9]+\\(\\) at ")
    add_test(NAME ${name}_${case}
      COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['interface_solve'], s['factors_on_disk']); sys.exit(0 if s['interface_solve'] == sys.argv[2] and s['factors_on_disk'] else 1)" ${out}/summary.json ${case})
    add_test(NAME ${name}_load_shares
      COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_lap_rows.py ${out}/joints.csv 21820 72000 20 1.27 20)
    set_tests_properties(${name}_${case} ${name}_load_shares PROPERTIES FIXTURES_REQUIRED ${name})
  endforeach()
endforeach()
# -interface_out_of_core false: the first failure stops the run.
boltnet_expect(factor_no_out_of_core 1 --status 3
  --match "FAILED: Load step 1 from load factor 0 to 1: MUMPS could not factor the 26472-dof Jacobian \\(INFOG\\(1\\) = -19"
  --match "or keep the factors on disk \\(-interface_out_of_core\\)"
  --reject "factoring again" --reject "cutting the increment" --
  $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${BOLTNET_OUT}/factor_no_out_of_core
  -output_fields false -patch_condense false -mat_mumps_icntl_23 30 -interface_out_of_core false)

# The user's own -mat_mumps_icntl_22 1 keeps the factors on disk from the start: summary.json says so
# (the reference: MUMPS's ICNTL(22) as given, and the closed-form load shares of the run); under the
# 1 MB cap the failure is not retried on disk again, and the advice does not send the user there.
foreach(ranks 1 2 3)
  set(out ${BOLTNET_OUT}/factor_user_out_of_core_np${ranks})
  add_test(NAME factor_user_out_of_core_np${ranks}
    COMMAND ${BOLTNET_EXPECT} --match "1 steps converged \\(0 cut-backs\\)" --reject "factoring again" --
            ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml
            -output_dir ${out} -output_fields false -patch_condense false -mat_mumps_icntl_22 1)
  set_tests_properties(factor_user_out_of_core_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_SETUP factor_user_out_of_core_np${ranks})
  add_test(NAME factor_user_out_of_core_summary_np${ranks}
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); sys.exit(0 if s['status']=='converged' and s['factors_on_disk'] else 'summary.json: factors_on_disk ' + str(s['factors_on_disk']))" ${out}/summary.json)
  add_test(NAME factor_user_out_of_core_load_shares_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_lap_rows.py ${out}/joints.csv 21820 72000 20 1.27 20)
  set_tests_properties(factor_user_out_of_core_summary_np${ranks} factor_user_out_of_core_load_shares_np${ranks} PROPERTIES FIXTURES_REQUIRED factor_user_out_of_core_np${ranks})
  boltnet_expect(factor_user_out_of_core_cap ${ranks} --status 3
    --match "FAILED: Load step 1 from load factor 0 to 1: MUMPS could not factor the 26472-dof Jacobian with its factors on disk \\(INFOG\\(1\\) = -19"
    --reject "factoring again" --reject "keep the factors on disk" --reject "cutting the increment" --
    ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml
    -output_dir ${BOLTNET_OUT}/factor_user_out_of_core_cap_np${ranks} -output_fields false -patch_condense false -mat_mumps_icntl_22 1 -mat_mumps_icntl_23 1)
endforeach()

# An allocation MUMPS cannot get (INFOG(1) = -13): ICNTL(14) = 2,000,000 makes MUMPS ask for 20,000
# times its in-core workspace estimate, hundreds of GB, which the kernel refuses (its default
# overcommit heuristics refuse one allocation larger than memory and swap); the message gives the
# size from INFOG(2) (millions of reals when negative, MUMPS users' guide). Out of core MUMPS sizes
# its workspace from the fronts alone and gets it: the step converges to the closed-form load
# shares. Where a kernel grants the first allocation (overcommit always), the test is skipped.
# -interface_memory_mb 1e9 (a petabyte) lets the factorisation try in core, against MUMPS's own
# estimate, which says it cannot (factor_memory_estimate_* below).
set(out ${BOLTNET_OUT}/factor_out_of_memory_np1)
add_test(NAME factor_out_of_memory_np1
  COMMAND sh -c "\"$0\" -scene \"$1\" -output_dir \"$2\" -output_fields false -patch_condense false -mat_mumps_icntl_14 2000000 -interface_memory_mb 1e9 > \"$2.txt\" 2>&1; rc=$?; cat \"$2.txt\"; if ! grep -q 'INFOG(1) = -13' \"$2.txt\" && [ $rc = 0 ]; then echo 'the kernel granted the allocation'; exit 77; fi; [ $rc = 0 ] && grep -Eq 'load step 1: MUMPS could not factor the 26472-dof Jacobian \\(INFOG\\(1\\) = -13, INFOG\\(2\\) = -[0-9]+\\): out of memory, an allocation of [0-9.e+]+ GB failed; factoring again with the factors on disk' \"$2.txt\" && grep -q '1 steps converged (0 cut-backs)' \"$2.txt\" && \"$3\" \"$4\" \"$2/joints.csv\" 21820 72000 20 1.27 20"
          $<TARGET_FILE:boltnet_driver> ${BOLTNET_SCENES}/lap-rows.yaml ${out} ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_lap_rows.py)
set_tests_properties(factor_out_of_memory_np1 PROPERTIES ENVIRONMENT "${BOLTNET_ENV}" SKIP_RETURN_CODE 77)

# Factors on disk from the start when MUMPS's analysis says they will not fit (docs/solver.md, "No
# null pivot"): its in-core estimate (INFO(15), summed over a node's ranks) against what the node
# has, or -interface_memory_mb. The reference that they really went to disk is MUMPS's own: under a
# 30 MB cap on its working memory per rank (-mat_mumps_icntl_23 30) lap-rows' factorisation fails in
# core (factor_out_of_core_* above: INFOG(1) = -19) and fits on disk; here it fits at the first
# attempt, with no retry, and converges to the closed-form load shares. 30 MB per rank is under
# MUMPS's in-core estimate on 1, 2 and 3 ranks (55, 78 and 106 MB summed over the ranks).
foreach(ranks 1 2 3)
  set(out ${BOLTNET_OUT}/factor_memory_estimate_np${ranks})
  math(EXPR mb "30 * ${ranks}")
  add_test(NAME factor_memory_estimate_np${ranks}
    COMMAND ${BOLTNET_EXPECT} --match "MUMPS's analysis estimates [0-9]+ MB to factor the 26472-dof Jacobian in memory, more than the ${mb} MB given by -interface_memory_mb: the factors go to disk"
            --match "1 steps converged \\(0 cut-backs\\)" --reject "factoring again" --reject "INFOG\\(1\\) = -19" --
            ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml
            -output_dir ${out} -output_fields false -patch_condense false -mat_mumps_icntl_23 30 -interface_memory_mb ${mb})
  set_tests_properties(factor_memory_estimate_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_SETUP factor_memory_estimate_np${ranks})
  add_test(NAME factor_memory_estimate_summary_np${ranks}
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); sys.exit(0 if s['status']=='converged' and s['factors_on_disk'] and s['cutbacks']==0 else 'summary.json: factors_on_disk ' + str(s['factors_on_disk']))" ${out}/summary.json)
  add_test(NAME factor_memory_estimate_load_shares_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_lap_rows.py ${out}/joints.csv 21820 72000 20 1.27 20)
  set_tests_properties(factor_memory_estimate_summary_np${ranks} factor_memory_estimate_load_shares_np${ranks} PROPERTIES FIXTURES_REQUIRED factor_memory_estimate_np${ranks})
endforeach()
# With what the node really has (MemAvailable): ICNTL(14) = 2,000,000 makes MUMPS's estimate
# hundreds of GB (factor_out_of_memory_np1 above), more than any node here has, so the factors go to
# disk before any allocation fails; the estimate of lap-rows as it is, 55 MB, leaves them in memory.
set(out ${BOLTNET_OUT}/factor_memory_available_np1)
boltnet_expect(factor_memory_available 1
  --match "more than the [0-9]+ MB the node has available: the factors go to disk"
  --match "1 steps converged \\(0 cut-backs\\)" --reject "INFOG\\(1\\) = -13" --reject "factoring again" --
  $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${out}
  -output_fields false -patch_condense false -mat_mumps_icntl_14 2000000)
add_test(NAME factor_memory_available_load_shares_np1
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_lap_rows.py ${out}/joints.csv 21820 72000 20 1.27 20)
set_tests_properties(factor_memory_available_load_shares_np1 PROPERTIES DEPENDS factor_memory_available_np1)
boltnet_expect(factor_memory_fits 1 --match "MUMPS's analysis: [0-9]+ MB in core, [0-9]+ MB out of core, on the node that needs most against the [0-9]+ MB it has available"
  --match "1 steps converged" --reject "the factors go to disk" --
  $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${BOLTNET_OUT}/factor_memory_fits
  -output_fields false -patch_condense false -info :mat)
# Who decides: -interface_out_of_core false, or the user's own -mat_mumps_icntl_22 0, keeps the
# factors in memory whatever the estimate, and the 30 MB cap then fails the run as MUMPS says (-19),
# with no retry; the advice names the option that would put them on disk.
boltnet_expect(factor_memory_estimate_off 1 --status 3
  --match "INFOG\\(1\\) = -19" --match "or keep the factors on disk \\(-interface_out_of_core\\)"
  --reject "the factors go to disk" --reject "factoring again" --
  $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${BOLTNET_OUT}/factor_memory_estimate_off
  -output_fields false -patch_condense false -mat_mumps_icntl_23 30 -interface_memory_mb 30 -interface_out_of_core false)
boltnet_expect(factor_memory_estimate_user 1 --status 3
  --match "INFOG\\(1\\) = -19" --match "or keep the factors on disk \\(-mat_mumps_icntl_22 1\\)"
  --reject "the factors go to disk" --reject "factoring again" --reject "with its factors on disk" --
  $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${BOLTNET_OUT}/factor_memory_estimate_user
  -output_fields false -patch_condense false -mat_mumps_icntl_23 30 -interface_memory_mb 30 -mat_mumps_icntl_22 0)
boltnet_expect(factor_memory_negative 1 --fail --max-lines 1 --match "-interface_memory_mb -5\\.? must be >= 0" --
  $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml -output_dir ${BOLTNET_OUT}/factor_memory_negative
  -output_fields false -interface_memory_mb -5)
# A run stopped by SIGTERM (a scheduler's time limit, timeout(1), mpirun passing on Ctrl-C) removes
# its factors from disk (drivers/ooc_files.hpp): the small plate grid with every factor out of core,
# stopped once MUMPS has written its files, on 1 rank and through mpirun on 2 and 3, leaves none of them;
# with the user's own MUMPS_OOC_PREFIX its files stay (the control: nobody else removes them).
foreach(mode_ranks "ours;1" "ours;2" "ours;3" "user;1")
  list(GET mode_ranks 0 mode)
  list(GET mode_ranks 1 ranks)
  set(_run $<TARGET_FILE:boltnet_driver>)
  if(ranks GREATER 1)
    set(_run ${BOLTNET_MPIRUN} ${ranks} --oversubscribe -x MUMPS_OOC_TMPDIR $<TARGET_FILE:boltnet_driver>)
  endif()
  add_test(NAME ooc_files_removed_on_sigterm_${mode}_np${ranks}
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/check_ooc_cleanup.sh ${mode} ${BOLTNET_OUT}/ooc_${mode}_np${ranks} --
            ${_run} -scene ${BOLTNET_OUT}/grid/small.yaml -output_dir ${BOLTNET_OUT}/ooc_${mode}_np${ranks}_out
            -output_fields false -mat_mumps_icntl_22 1 -load_steps 500)
  set_tests_properties(ooc_files_removed_on_sigterm_${mode}_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED grid_scene TIMEOUT 600)
endforeach()
