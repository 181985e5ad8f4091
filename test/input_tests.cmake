# Bad input and untrustworthy output (docs/scenes.md, "Limits" and "Errors"). Each bad input must give
# one line naming the input (file, line, column, option), a non-zero exit, and leave what an earlier
# run wrote untouched (the sentinel of test/CMakeLists.txt). Included from test/CMakeLists.txt, which
# defines boltnet_expect, _bad (--fail --unchanged sentinel) and _run (the driver on 2 ranks).

# The pure parsers (tables, scene files, Gmsh files) against hand-made inputs.
add_executable(test_input test_input.cpp ${PROJECT_SOURCE_DIR}/lib/io/table.cpp ${PROJECT_SOURCE_DIR}/lib/io/scene_yaml.cpp ${PROJECT_SOURCE_DIR}/lib/mesh/gmsh.cpp)
target_include_directories(test_input PRIVATE ${PROJECT_SOURCE_DIR}/lib)
target_compile_definitions(test_input PRIVATE BOLTNET_TEST_DATA="${CMAKE_CURRENT_SOURCE_DIR}/data")
target_link_libraries(test_input PRIVATE GTest::gtest GTest::gtest_main yaml)
gtest_discover_tests(test_input)

set(_one --max-lines 1)
# Plates: 10^9 elements used to end in an uncaught std::bad_alloc; -2^31 - 1 wrapped to a positive
# 32-bit count and did the same. Both are refused before any mesh is allocated.
boltnet_expect(bad_plate_huge 1 ${_bad} ${_one} --match "huge-plate.patches.csv line 3, column 'nx': 1000000000 is out of range: it must lie in \\[1, 1000000\\]"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml -output_dir ${BOLTNET_OUT}/bad -scene_patches ${BOLTNET_TEST_SCENES}/huge-plate.patches.csv)
boltnet_expect(bad_plate_negative 2 ${_bad} --match "negative-plate.patches.csv line 3, column 'nx': -2147483649 is out of range"
  -- ${_run} -scene ${BOLTNET_SCENES}/fig3a.yaml -scene_patches ${BOLTNET_TEST_SCENES}/negative-plate.patches.csv)
# Ids past 2^31 - 1 used to be truncated to 32 bits (4294967297 became patch 1, silently).
boltnet_expect(bad_id_64bit 1 ${_bad} ${_one} --match "big-id.patches.csv line 4, column 'id': 99999999999 is out of range: it must lie in \\[0, 2147483647\\]"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -scene_patches ${BOLTNET_TEST_SCENES}/big-id.patches.csv)
boltnet_expect(bad_joint_patch_64bit 2 ${_bad} --match "big-id.joints.csv line 3, column 'patch_b': 4294967297 is out of range"
  -- ${_run} -scene ${BOLTNET_SCENES}/fig3c.yaml -scene_joints ${BOLTNET_TEST_SCENES}/big-id.joints.csv)
# A duplicated column used to be accepted (the first one read, the second ignored).
boltnet_expect(bad_duplicate_column 1 ${_bad} ${_one} --match "duplicate-column.patches.csv line 2: column 'x' appears twice in the header"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -scene_patches ${BOLTNET_TEST_SCENES}/duplicate-column.patches.csv)
# A UTF-8 byte-order mark used to become part of the first column's name ("missing column 'id'"):
# the table with one gives fig3c's results exactly.
boltnet_run(fig3c_bom 1 ${BOLTNET_SCENES}/fig3c.yaml -scene_patches ${BOLTNET_TEST_SCENES}/bom.patches.csv)
add_test(NAME fig3c_bom_same_results
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/fig3c_np1/joints.csv ${BOLTNET_OUT}/fig3c_bom_np1/joints.csv 0)
set_tests_properties(fig3c_bom_same_results PROPERTIES FIXTURES_REQUIRED "fig3c_np1;fig3c_bom_np1")
# -load_steps 10^8 used to abort in std::bad_alloc after the output directory was emptied.
boltnet_expect(bad_load_steps_huge 2 ${_bad} --match "-load_steps 100000000 over 3 segment\\(s\\) of the load path is more than the limit of 1000000 steps"
  -- ${_run} -scene ${BOLTNET_SCENES}/fig3c.yaml -load_steps 100000000)
# An integer option past 32 bits used to be truncated by PETSc (99999999999 -> 1215752191 steps).
boltnet_expect(bad_option_int64 1 ${_bad} ${_one} --match "-load_steps 99999999999: out of range"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -load_steps 99999999999)
# A value of the wrong type: PETSc's message used not to name the option.
boltnet_expect(bad_option_type_real 2 ${_bad} --match "option -joint_bolt_kt: Input string abc has no numeric value"
  -- ${_run} -scene ${BOLTNET_SCENES}/fig3c.yaml -joint_bolt_kt abc)
boltnet_expect(bad_option_type_bool 1 ${_bad} ${_one} --match "option -patch_balance: Unknown logical value: maybe"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -patch_balance maybe)
boltnet_expect(bad_option_type_int 1 ${_bad} ${_one} --match "-load_steps abc: not a whole number"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -load_steps abc)
# A misspelled section (lod: for load:) used to be ignored: the run went on with the default load.
boltnet_expect(bad_section_misspelled 2 ${_bad} --match "misspelled-section.yaml line 13: unknown section 'lod' \\(-lod_steps\\)"
  -- ${_run} -scene ${BOLTNET_TEST_SCENES}/misspelled-section.yaml)
# A YAML syntax error used to say "YAML parser loading error" with no file or line.
boltnet_expect(bad_yaml_syntax 1 ${_bad} ${_one} --match "syntax-error.yaml line 15, column 8: did not find expected ',' or '.' \\(while parsing a flow sequence at line 14\\)"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/syntax-error.yaml -output_dir ${BOLTNET_OUT}/bad)

# One error, one line (it used to print about 43 lines of PETSc's traceback and, on 2 ranks,
# MPI_ABORT's banner): on 1, 2 and 3 ranks every rank ends cleanly and rank 0 prints the message.
# mpiexec --quiet drops Open MPI's own notice of a non-zero exit, which is not the program's.
foreach(ranks 1 2 3)
  boltnet_expect(error_one_line ${ranks} ${_bad} --max-lines 1 --match "^boltnet: error: Joint type 'bolt' .*gap = -0.1 must be"
    -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe --quiet $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -joint_bolt_gap -0.1)
endforeach()

# With -options_left an unused option stops the run before the solve: nothing is written.
boltnet_expect(unused_option_before_solve 2 --fail --absent ${BOLTNET_OUT}/unused_early/joints.csv
  --match "option\\(s\\) given but never used: -snes_linesearch_typo \\(-options_left. checked before the solve"
  -- ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml
  -output_dir ${BOLTNET_OUT}/unused_early -options_left -snes_linesearch_typo basic -snes_view -snes_converged_reason)

# A full disk (requirement: output that cannot lie): /dev/full in place of a result file. It used to
# exit 0 with joints.csv cut and an empty summary.json.
set(_full ${CMAKE_CURRENT_SOURCE_DIR}/check_full_disk.sh)
add_test(NAME full_disk_joints_np1 COMMAND ${_full} joints.csv ${BOLTNET_OUT}/full_joints "^boltnet: error: Cannot write .*full_joints/joints.csv: No space left on device"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/full_joints -load_steps 2)
add_test(NAME full_disk_summary_np2 COMMAND ${_full} summary.json.tmp ${BOLTNET_OUT}/full_summary "boltnet: error: Cannot write .*full_summary/summary.json.tmp: No space left on device"
  -- ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/full_summary -load_steps 2)
# A failure inside the solve (the fields written at each converged step) names its cause.
add_test(NAME full_disk_fields_np2 COMMAND ${_full} fields.xdmf.tmp ${BOLTNET_OUT}/full_fields "boltnet: error: The load path stopped at load factor .*Cannot write the fields of step 1 .*fields.xdmf.tmp: No space left on device"
  -- ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml -output_dir ${BOLTNET_OUT}/full_fields -load_steps 2)
set_tests_properties(full_disk_joints_np1 full_disk_summary_np2 full_disk_fields_np2 PROPERTIES SKIP_RETURN_CODE 77 ENVIRONMENT "${BOLTNET_ENV}")
set_tests_properties(full_disk_summary_np2 full_disk_fields_np2 PROPERTIES PROCESSORS 2)
# An HDF5 write error through PETSc's viewer: fields.h5 cannot be created (a directory is in the way).
boltnet_expect(fields_h5_error 1 --fail --max-lines 2 --match "Cannot write the fields of step 1 in .*fields.h5 .*H5Fcreate"
  -- sh -c "rm -rf \"$1\" && mkdir -p \"$1/fields.h5/x\" && \"$0\" -scene \"$2\" -output_dir \"$1\" -load_steps 2" $<TARGET_FILE:boltnet_driver> ${BOLTNET_OUT}/h5_dir ${BOLTNET_SCENES}/fig3a.yaml)

# Fuzz regressions (docs/fuzzing.md): every input kept under test/data/fuzz/<target>/ (inputs a fuzzer
# crashed on, and inputs that broke the parsers before they were hardened) through the fuzz target's
# own checks, without libFuzzer; scripts/sanitize runs them with the sanitizers.
set(_fuzz_sources_table ${PROJECT_SOURCE_DIR}/lib/io/table.cpp)
set(_fuzz_sources_gmsh ${PROJECT_SOURCE_DIR}/lib/mesh/gmsh.cpp)
set(_fuzz_sources_scene ${PROJECT_SOURCE_DIR}/lib/io/scene_yaml.cpp)
set(_fuzz_sources_nastran ${BOLTNET_NASTRAN_SOURCES} ${PROJECT_SOURCE_DIR}/lib/shell/material.cpp)
foreach(target table gmsh scene nastran)
  add_executable(fuzz_replay_${target} fuzz/replay.cpp fuzz/fuzz_${target}.cpp ${_fuzz_sources_${target}})
  target_include_directories(fuzz_replay_${target} PRIVATE ${PROJECT_SOURCE_DIR}/lib)
  target_link_libraries(fuzz_replay_${target} PRIVATE yaml PkgConfig::PETSC MPI::MPI_C)
  file(GLOB _inputs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/data/fuzz/${target}/*)
  add_test(NAME fuzz_regressions_${target} COMMAND fuzz_replay_${target} ${_inputs})
  set_tests_properties(fuzz_regressions_${target} PROPERTIES ENVIRONMENT "${BOLTNET_ENV}" PASS_REGULAR_EXPRESSION "replay: [1-9][0-9]* input\\(s\\) ran without a crash")
endforeach()

# The fastener table is read and checked by rank 0 alone (io/scene.cpp, patch/layout.cpp): an error
# in it, or in what only the whole joint list shows (an id given twice, a joint naming no patch),
# must still stop every rank with the one message, on 1 and 3 ranks (ranks 1 and 2 hold no joint
# until the layout sends them theirs, so a rank left waiting would hang the test until its timeout).
set(_run3 ${BOLTNET_MPIRUN} 3 --oversubscribe $<TARGET_FILE:boltnet_driver> -output_dir ${BOLTNET_OUT}/bad)
foreach(case "bad;bad.joints.csv line 2, column 'patch_b': 'one' is not a whole number"
             "unknown-patch;Joint 0 names patch 7 which does not exist"
             "twice;Joint id 0 is given twice"
             "type-case;type-case.joints.csv line 2: joint type 'Bolt' must be lower-case letters and digits")
  list(GET case 0 _table)
  list(GET case 1 _message)
  boltnet_expect(rank0_table_${_table} 1 ${_bad} ${_one} --match "${_message}"
    -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -scene_joints ${BOLTNET_TEST_SCENES}/${_table}.joints.csv)
  boltnet_expect(rank0_table_${_table} 3 ${_bad} --match "${_message}"
    -- ${_run3} -scene ${BOLTNET_SCENES}/fig3c.yaml -scene_joints ${BOLTNET_TEST_SCENES}/${_table}.joints.csv)
  set_tests_properties(rank0_table_${_table}_np3 PROPERTIES TIMEOUT 120)
endforeach()
