# Results engineers read (docs/output.md): element results against closed forms through the API,
# the files opened by meshio, fields written in parallel equal to one rank's.

# Resultants and surface stresses of a strip in tension, pure bending and as a cantilever, against
# their closed forms, in the element and the material frame, at 1, 2 and 3 ranks (the strip is cut
# into patches on several ranks: elements on the cut read the other patch's nodes).
add_executable(test_element_results test_element_results.c)
target_link_libraries(test_element_results PRIVATE boltnet m)
foreach(ranks 1 2 3)
  boltnet_expect(element_results ${ranks} --match "test_element_results: PASS" --
    ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:test_element_results> -options_left)
endforeach()
