# Shell element tests. The kernels are compiled into the tests directly (as test_joint_law
# does with the joint laws), so the shell tests do not depend on the rest of libboltnet.
set(BOLTNET_SHELL_SOURCES ${PROJECT_SOURCE_DIR}/lib/shell/material.cpp ${PROJECT_SOURCE_DIR}/lib/shell/element.cpp
                          ${PROJECT_SOURCE_DIR}/lib/shell/triangle.cpp)

# Kernel unit tests: sections, stiffness symmetry, rigid-body modes, loads, bad input (no PETSc).
add_executable(test_shell_element test_shell_element.cpp ${BOLTNET_SHELL_SOURCES})
target_include_directories(test_shell_element PRIVATE ${PROJECT_SOURCE_DIR}/lib)
target_link_libraries(test_shell_element PRIVATE GTest::gtest GTest::gtest_main)
gtest_discover_tests(test_shell_element TEST_PREFIX shell.)

# The triangle and the director kinematics at element level (no PETSc).
add_executable(test_shell_triangle test_shell_triangle.cpp ${BOLTNET_SHELL_SOURCES})
target_include_directories(test_shell_triangle PRIVATE ${PROJECT_SOURCE_DIR}/lib)
target_link_libraries(test_shell_triangle PRIVATE GTest::gtest GTest::gtest_main)
gtest_discover_tests(test_shell_triangle TEST_PREFIX shell.)

# Global solves (sequential PETSc AIJ + LU in the test harness) on quadrilateral, triangle and mixed
# meshes: patch tests, laminates against CLT, plates, the MacNeal-Harder set, the pinched shells, the
# skew plate. Its own main (PETSc-aware); `test_shell_solve --table` prints the convergence tables
# (scripts/shell-convergence).
add_executable(test_shell_solve test_shell_solve.cpp shell_tables.cpp shell_harness.cpp shell_benchmarks.cpp shell_exact.cpp
                                ${BOLTNET_SHELL_SOURCES})
target_include_directories(test_shell_solve PRIVATE ${PROJECT_SOURCE_DIR}/lib)
target_link_libraries(test_shell_solve PRIVATE GTest::gtest PkgConfig::PETSC MPI::MPI_C)
gtest_discover_tests(test_shell_solve TEST_PREFIX shell.)
