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
