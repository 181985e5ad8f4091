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

# A factorisation that fails for want of memory stops the run at once, saying so (exit 3, summary.json
# "failed" with MUMPS's INFOG(1)), instead of cutting the load step back eight times and factoring the
# same matrix again. The reference is MUMPS's own diagnosis: ICNTL(23) = 1 caps its working memory at
# 1 MB per rank, which no factorisation of lap-rows' 26,472 dof fits (INFOG(1) = -19).
foreach(ranks 1 2 3)
  set(out ${BOLTNET_OUT}/factor_memory_cap_np${ranks})
  boltnet_expect(factor_memory_cap ${ranks} --status 3
    --match "FAILED: Load step 1 from load factor 0 to 1: MUMPS could not factor the 26472-dof Jacobian \\(INFOG\\(1\\) = -19"
    --match "mat_mumps_icntl_23 limits"
    --reject "cutting the increment" --
    ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/lap-rows.yaml
    -output_dir ${out} -output_fields false -patch_condense false -mat_mumps_icntl_23 1)
  add_test(NAME factor_memory_cap_summary_np${ranks}
    COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); sys.exit(0 if s['status']=='failed' and 'INFOG(1) = -19' in s['message'] and s['cutbacks']==0 else 'summary.json: ' + s['status'] + ', ' + s['message'])" ${out}/summary.json)
  set_tests_properties(factor_memory_cap_summary_np${ranks} PROPERTIES DEPENDS factor_memory_cap_np${ranks})
endforeach()

# An allocation MUMPS cannot get (INFOG(1) = -13): ICNTL(14) = 2,000,000 asks for 20,000 times its
# workspace estimate, hundreds of GB, which the kernel refuses (its default overcommit heuristics
# refuse one allocation larger than memory and swap). The message gives the size from INFOG(2)
# (millions of reals when negative, MUMPS users' guide). Where a kernel grants it (overcommit
# always), the run converges and the test is skipped.
set(out ${BOLTNET_OUT}/factor_out_of_memory_np1)
add_test(NAME factor_out_of_memory_np1
  COMMAND sh -c "\"$0\" -scene \"$1\" -output_dir \"$2\" -output_fields false -patch_condense false -mat_mumps_icntl_14 2000000 > \"$2.txt\" 2>&1; rc=$?; cat \"$2.txt\"; if [ $rc = 0 ]; then echo 'the kernel granted the allocation'; exit 77; fi; [ $rc = 3 ] && grep -Eq 'INFOG\\(1\\) = -13, INFOG\\(2\\) = -[0-9]+\\): out of memory, an allocation of [0-9.e+]+ GB failed' \"$2.txt\" && ! grep -q 'cutting the increment' \"$2.txt\""
          $<TARGET_FILE:boltnet_driver> ${BOLTNET_SCENES}/lap-rows.yaml ${out})
set_tests_properties(factor_out_of_memory_np1 PROPERTIES ENVIRONMENT "${BOLTNET_ENV}" SKIP_RETURN_CODE 77)
