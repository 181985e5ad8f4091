# Shell element sources: target_sources(boltnet PRIVATE ...).
# Pure C++ kernels (no PETSc): sections (isotropic, laminate by CLT), the four-node MITC4 shell and the
# three-node MITC3+ / OPT shell (shared director kinematics: kinematics.hpp).
target_sources(boltnet PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/material.cpp
  ${CMAKE_CURRENT_LIST_DIR}/element.cpp
  ${CMAKE_CURRENT_LIST_DIR}/triangle.cpp
  ${CMAKE_CURRENT_LIST_DIR}/resultants.cpp)
