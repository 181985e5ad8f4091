# Nastran reader tests (docs/nastran.md). The reader is pure C++: the unit tests compile its sources
# (and lib/shell/material.cpp for the sections) without PETSc or MPI.
add_executable(test_nastran ${CMAKE_CURRENT_SOURCE_DIR}/test_nastran.cpp ${CMAKE_CURRENT_SOURCE_DIR}/test_nastran_errors.cpp
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
