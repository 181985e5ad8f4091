# Nastran reader tests (docs/nastran.md). The reader is pure C++: the unit tests compile its sources
# (and lib/shell/material.cpp for the sections) without PETSc or MPI.
add_executable(test_nastran ${CMAKE_CURRENT_SOURCE_DIR}/test_nastran.cpp ${CMAKE_CURRENT_SOURCE_DIR}/test_nastran_errors.cpp ${CMAKE_CURRENT_SOURCE_DIR}/test_nastran_model.cpp
  ${BOLTNET_NASTRAN_SOURCES} ${PROJECT_SOURCE_DIR}/lib/shell/material.cpp)
target_include_directories(test_nastran PRIVATE ${PROJECT_SOURCE_DIR}/lib)
target_link_libraries(test_nastran PRIVATE GTest::gtest GTest::gtest_main)
target_compile_definitions(test_nastran PRIVATE BOLTNET_NASTRAN_DATA="${CMAKE_CURRENT_SOURCE_DIR}/data/nastran")
gtest_discover_tests(test_nastran TEST_PREFIX nastran.)

# The PETSc-facing wrapper through nastran-summary (requirement 3): a reader error becomes a PETSc
# error with the same file, line and field on every rank and a non-zero exit; a good deck prints
# its summary on 1 and 2 ranks with no unused option.
set(_ns $<TARGET_FILE:nastran_summary>)
set(_nd ${CMAKE_CURRENT_SOURCE_DIR}/data/nastran)
foreach(ranks 1 2)
  boltnet_expect(nastran_summary_cards ${ranks} --match "^cards used: 49$" --match "^  CBAR 1 \\(first at .*cards.bdf:85\\)$"
    --match "^    force \\[17.4, 1.8, -13.5\\] moment about the origin \\[-10.725, 48.3625, 2.1\\]$" --match "There are no unused options"
    -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe ${_ns} -nastran_deck ${_nd}/cards.bdf -options_left)
  boltnet_expect(nastran_summary_bad_deck ${ranks} --fail --match "PETSC ERROR: .*bad-field.bdf:5: CQUAD4 12, field 6 \\(G3\\): grid 33 is not defined"
    -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe ${_ns} -nastran_deck ${_nd}/bad-field.bdf)
endforeach()
boltnet_expect(nastran_summary_no_deck 1 --fail --match "No deck: give -nastran_deck" -- ${_ns})
boltnet_expect(nastran_summary_unused_option 1 --fail --match "option\\(s\\) given but never used: -nastran_dek"
  -- ${_ns} -nastran_deck ${_nd}/cards.bdf -options_left -nastran_dek x)
boltnet_expect(nastran_summary_missing_properties 1 --match "1 properties of 1 shells are not PSHELL or PCOMP cards"
  -- ${_ns} -nastran_deck ${_nd}/missing-property.bdf -nastran_allow_missing_properties)

# The bolted wing box of scripts/make-nastran-wingbox (requirements 1, 2 and 5): the same model in
# small, large and free field (INCLUDE, two subcases, every supported card but CFAST and CONM2). Each
# summary matches the generator's own count of cards, bounding box, constrained dof and load
# resultants (computed without the reader), and the three summaries agree.
set(_wb ${BOLTNET_OUT}/nastran-wingbox)
add_test(NAME make_nastran_wingbox COMMAND ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/make-nastran-wingbox ${_wb})
set_tests_properties(make_nastran_wingbox PROPERTIES FIXTURES_SETUP nastran_wingbox)
set(_wb_summaries)
foreach(fmt small large free)
  add_test(NAME nastran_wingbox_${fmt}
    COMMAND sh -c "\"$0\" -nastran_deck \"$1/wingbox-$2.bdf\" > \"$1/$2.txt\" && ${BOLTNET_PYTHON} \"$3\" \"$1/manifest.json\" \"$1/$2.txt\""
            ${_ns} ${_wb} ${fmt} ${CMAKE_CURRENT_SOURCE_DIR}/check_nastran_wingbox.py)
  set_tests_properties(nastran_wingbox_${fmt} PROPERTIES FIXTURES_REQUIRED nastran_wingbox FIXTURES_SETUP nastran_wingbox_${fmt} ENVIRONMENT "${BOLTNET_ENV}")
  list(APPEND _wb_summaries ${_wb}/${fmt}.txt)
endforeach()
add_test(NAME nastran_wingbox_formats_agree COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_nastran_wingbox.py --same ${_wb_summaries})
set_tests_properties(nastran_wingbox_formats_agree PROPERTIES FIXTURES_REQUIRED "nastran_wingbox_small;nastran_wingbox_large;nastran_wingbox_free")
# scripts/verify-nastran-decks over the generated decks: every deck reads, the table lists them.
boltnet_expect(verify_nastran_decks 1 --match "^\\| wingbox-small.bdf \\| yes \\| CBUSH.nbsp.36 " --match "^\\| wingbox-free-mesh.bdf \\| yes \\|"
  -- ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/verify-nastran-decks ${_wb} --summary ${_ns})
set_tests_properties(verify_nastran_decks_np1 PROPERTIES FIXTURES_REQUIRED nastran_wingbox)
