# Algebraic multigrid on the uncondensed path (docs/solver.md, "Iterative solvers"): the Jacobian's
# near-null space, and GAMG solving a plate grid to the answer of LU.

# The six near-null vectors are rigid-body modes: the unconstrained stiffness of a free model (a
# curved panel of quadrilaterals, a plate of triangles and a rigid patch, joined by fasteners) maps
# each to zero, ||K z|| <= 1e-11 ||K|| ||z|| (test/test_near_null_space.c); kept whole and cut into
# seamed patches over 1 to 3 ranks, and condensed; -interface_near_null_space false attaches none.
add_executable(test_near_null_space test_near_null_space.c)
target_link_libraries(test_near_null_space PRIVATE boltnet m)
foreach(ranks 1 2 3)
  boltnet_expect(near_null_space_whole ${ranks} --match "test_near_null_space: PASS" --
    ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:test_near_null_space> -patch_condense false -patch_max_nodes 24 -options_left)
endforeach()
boltnet_expect(near_null_space_condensed 2 --match "test_near_null_space: PASS" --
  ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:test_near_null_space> -options_left)
boltnet_expect(near_null_space_off 1 --match "no near-null space attached" --match "test_near_null_space: PASS" --
  $<TARGET_FILE:test_near_null_space> -patch_condense false -interface_near_null_space false -options_left)
