# Triangles and mixed meshes end to end: generated plates, a Gmsh part, the cut into patches and
# seams, condensation, the public C API and the fields. Included by test/CMakeLists.txt (its helpers
# boltnet_run, boltnet_expect, boltnet_compare_ranks). The mesh and patch-operator pieces are unit
# tests (test_mesh_triangles.cpp, test_patch_operator.cpp).

# The strip of test/scenes/strip.yaml, meshed in quadrilaterals, triangles or both, in tension and in
# bending through the driver, against the exact solution at every node and step (check_strip.py): on
# 1 rank one patch, on 2 (and, for triangles, 3) ranks cut into patches joined by seams. Measured:
# tension 1e-14; bending 2e-11 (quadrilaterals), 1.1e-9 (triangles), 5e-10 (mixed): the round-off
# of the element matrices amplified by the ratio of the shear to the bending stiffness, (h / t)^2 ~
# 100 here, the same with a dense solve in long double; hence rtol 1e-8.
foreach(kind quad tri mixed)
  if(kind STREQUAL quad)
    set(_patches ${BOLTNET_TEST_SCENES}/strip.patches.csv)
  else()
    set(_patches ${BOLTNET_TEST_SCENES}/strip-${kind}.patches.csv)
  endif()
  set(_ranks 1 2)
  if(kind STREQUAL tri)
    list(APPEND _ranks 3) # more patches and seams through triangles
  endif()
  foreach(load tension bending)
    foreach(ranks ${_ranks})
      boltnet_run(strip_${kind}_${load} ${ranks} ${BOLTNET_TEST_SCENES}/strip.yaml -scene_patches ${_patches}
        -scene_bcs ${BOLTNET_TEST_SCENES}/strip-${load}.bcs.csv)
      add_test(NAME strip_${kind}_${load}_exact_np${ranks}
        COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_strip.py ${BOLTNET_OUT}/strip_${kind}_${load}_np${ranks} ${load} 72000 20 1.27 1e-8)
      set_tests_properties(strip_${kind}_${load}_exact_np${ranks} PROPERTIES FIXTURES_REQUIRED strip_${kind}_${load}_np${ranks})
    endforeach()
  endforeach()
endforeach()
# The 2-rank strips were cut (a seam through triangles).
add_test(NAME strip_tri_cut COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_balance.py ${BOLTNET_OUT}/strip_tri_tension_np2/summary.json 1.5)
set_tests_properties(strip_tri_cut PROPERTIES FIXTURES_REQUIRED strip_tri_tension_np2)
# The fields of triangle and mixed parts (docs/output.md): fields.xdmf names what fields.h5 holds,
# the clamped edge does not move, 2 ranks write what 1 rank writes.
foreach(kind tri mixed)
  add_test(NAME strip_${kind}_fields
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fields.py ${BOLTNET_OUT}/strip_${kind}_bending_np2 ${BOLTNET_TEST_SCENES}/strip.joints.csv
            --fixed 0,x,0,all --ref ${BOLTNET_OUT}/strip_${kind}_bending_np1 --rtol 1e-9 --elements ${kind})
  set_tests_properties(strip_${kind}_fields PROPERTIES FIXTURES_REQUIRED "strip_${kind}_bending_np1;strip_${kind}_bending_np2")
endforeach()
# The element results of those strips in fields.h5 (docs/output.md): N_xx = F / w in tension and
# M_xx = M / w in bending, every other resultant 0, surface stresses N / t +- 6 M / t^2, at every
# element of quadrilaterals, triangles or both, on every rank count above: the states the elements
# represent exactly (check_stresses.py, 1e-8 of each quantity's scale; measured at most 1.9e-9). A
# moment varying along the strip is not exact for the triangles (docs/output.md).
foreach(kind quad tri mixed)
  set(_ranks 1 2)
  if(kind STREQUAL tri)
    list(APPEND _ranks 3)
  endif()
  foreach(ranks ${_ranks})
    add_test(NAME strip_${kind}_tension_stresses_np${ranks}
      COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_stresses.py ${BOLTNET_OUT}/strip_${kind}_tension_np${ranks} --length 150 --width 20 --thickness 1.27 --fx 1)
    add_test(NAME strip_${kind}_bending_stresses_np${ranks}
      COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_stresses.py ${BOLTNET_OUT}/strip_${kind}_bending_np${ranks} --length 150 --width 20 --thickness 1.27 --my 1)
    set_tests_properties(strip_${kind}_tension_stresses_np${ranks} PROPERTIES FIXTURES_REQUIRED strip_${kind}_tension_np${ranks})
    set_tests_properties(strip_${kind}_bending_stresses_np${ranks} PROPERTIES FIXTURES_REQUIRED strip_${kind}_bending_np${ranks})
  endforeach()
endforeach()
# meshio reads the Mixed topology of triangle and mixed parts written by 2 ranks.
foreach(kind tri mixed)
  add_test(NAME strip_${kind}_meshio COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_meshio.py ${BOLTNET_OUT}/strip_${kind}_bending_np2)
  set_tests_properties(strip_${kind}_meshio PROPERTIES FIXTURES_REQUIRED strip_${kind}_bending_np2)
endforeach()
boltnet_expect(bad_plate_elements 1 ${_bad} --match "bad-elements.patches.csv line 4, column 'elements': 'hexa' is not quad, tri or mixed"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3a.yaml -output_dir ${BOLTNET_OUT}/bad -scene_patches ${BOLTNET_TEST_SCENES}/bad-elements.patches.csv)

# Cutting a triangle mesh changes where element stiffness is added, not the model: fig3b's plates
# split into triangles (contact bolts coming into bearing one after the other), cut into patches of
# at most 100 nodes joined by seams of triangles, on 1 and 2 ranks, give the uncut run's joints.csv to
# 1e-9 of each quantity's scale; the patches kept whole (-patch_condense false) give what the
# condensed ones give, cut and uncut; the bolts bear in the order of their clearances.
set(_fig3b_tri ${BOLTNET_SCENES}/fig3b.yaml -scene_patches ${BOLTNET_TEST_SCENES}/fig3b-tri.patches.csv -load_steps 30)
boltnet_run(fig3b_tri 1 ${_fig3b_tri} -patch_max_nodes 0)
boltnet_run(fig3b_tri_whole 1 ${_fig3b_tri} -patch_max_nodes 0 -patch_condense false)
boltnet_run(fig3b_tri_seams_whole 1 ${_fig3b_tri} -patch_max_nodes 100 -patch_condense false)
foreach(ranks 1 2)
  boltnet_run(fig3b_tri_seams ${ranks} ${_fig3b_tri} -patch_max_nodes 100)
  add_test(NAME fig3b_tri_seams_same_model_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/fig3b_tri_np1/joints.csv ${BOLTNET_OUT}/fig3b_tri_seams_np${ranks}/joints.csv 1e-9)
  set_tests_properties(fig3b_tri_seams_same_model_np${ranks} PROPERTIES FIXTURES_REQUIRED "fig3b_tri_np1;fig3b_tri_seams_np${ranks}")
endforeach()
add_test(NAME fig3b_tri_seams_cut COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_balance.py ${BOLTNET_OUT}/fig3b_tri_seams_np1/summary.json 1.0)
set_tests_properties(fig3b_tri_seams_cut PROPERTIES FIXTURES_REQUIRED fig3b_tri_seams_np1)
add_test(NAME fig3b_tri_condensed_vs_whole
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/fig3b_tri_np1/joints.csv ${BOLTNET_OUT}/fig3b_tri_whole_np1/joints.csv 1e-9)
set_tests_properties(fig3b_tri_condensed_vs_whole PROPERTIES FIXTURES_REQUIRED "fig3b_tri_np1;fig3b_tri_whole_np1")
add_test(NAME fig3b_tri_seams_condensed_vs_whole
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/fig3b_tri_seams_np1/joints.csv ${BOLTNET_OUT}/fig3b_tri_seams_whole_np1/joints.csv 1e-9)
set_tests_properties(fig3b_tri_seams_condensed_vs_whole PROPERTIES FIXTURES_REQUIRED "fig3b_tri_seams_np1;fig3b_tri_seams_whole_np1")
add_test(NAME fig3b_tri_bearing_order
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fig3b.py ${BOLTNET_OUT}/fig3b_tri_np1/joints.csv 1,2,3,4)
set_tests_properties(fig3b_tri_bearing_order PROPERTIES FIXTURES_REQUIRED fig3b_tri_np1)

# A Gmsh file with triangles (test/data/tri-lap.msh): gmsh-lap's skin meshed with two triangles and
# a quadrilateral, its doubler with two triangles (the fastener lies on the diagonal between them);
# statics: the fastener carries the doubler's whole load, on 1 and 2 ranks, and the fields hold both
# element kinds with the clamped curve at rest.
foreach(ranks 1 2)
  boltnet_run(gmsh_tri_lap ${ranks} ${BOLTNET_TEST_SCENES}/gmsh-lap.yaml -scene_patches ${BOLTNET_TEST_SCENES}/gmsh-tri-lap.patches.csv)
  add_test(NAME gmsh_tri_lap_statics_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_statics.py ${BOLTNET_OUT}/gmsh_tri_lap_np${ranks}/joints.csv 7 f_t1 1 1e-8)
  set_tests_properties(gmsh_tri_lap_statics_np${ranks} PROPERTIES FIXTURES_REQUIRED gmsh_tri_lap_np${ranks})
endforeach()
boltnet_compare_ranks(gmsh_tri_lap 1e-9 2)
add_test(NAME gmsh_tri_lap_fields
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fields.py ${BOLTNET_OUT}/gmsh_tri_lap_np2 ${BOLTNET_TEST_SCENES}/gmsh-lap.joints.csv
          --fixed 1,x,0,all --ref ${BOLTNET_OUT}/gmsh_tri_lap_np1 --rtol 1e-9 --elements mixed)
set_tests_properties(gmsh_tri_lap_fields PROPERTIES FIXTURES_REQUIRED "gmsh_tri_lap_np1;gmsh_tri_lap_np2")

# The public C API (boltnet.h): a mixed mesh through BoltnetAssemblyAddShellPatchElements against the
# strip's closed form, bad element arrays refused, at 1, 2 and 3 ranks (test_shell_elements.c).
add_executable(test_shell_elements test_shell_elements.c)
target_link_libraries(test_shell_elements PRIVATE boltnet m)
foreach(ranks 1 2 3)
  boltnet_expect(shell_elements ${ranks} --match "test_shell_elements: PASS" --match "There are no unused options"
    -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:test_shell_elements> -options_left -malloc_debug -malloc_dump)
  set_tests_properties(shell_elements_np${ranks} PROPERTIES FAIL_REGULAR_EXPRESSION "bytes [A-Za-z_0-9]+\\(\\) at ")
endforeach()
