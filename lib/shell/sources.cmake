# Shell element sources (issue 3): target_sources(boltnet PRIVATE ...).
# Pure C++ kernels (no PETSc): sections (isotropic, laminate by CLT) and the four-node MITC4 shell
# (director kinematics: kinematics.hpp).
target_sources(boltnet PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/material.cpp
  ${CMAKE_CURRENT_LIST_DIR}/element.cpp)
