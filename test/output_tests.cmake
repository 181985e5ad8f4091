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

# The element results in fields.h5 against the cantilever strip's closed forms (N, M linear in x, Q,
# surface stresses) at 1, 2 and 3 ranks; on 2 and 3 ranks every dataset equals the 1-rank file
# (1e-9 of its scale): the parallel writer puts each rank's rows where one rank would.
foreach(ranks 1 2 3)
  boltnet_run(strip_cantilever ${ranks} ${BOLTNET_TEST_SCENES}/strip-cantilever.yaml)
  add_test(NAME strip_cantilever_stresses_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_stresses.py ${BOLTNET_OUT}/strip_cantilever_np${ranks}
            --length 150 --width 20 --thickness 2 --fz 1000 --fx 2000)
  set_tests_properties(strip_cantilever_stresses_np${ranks} PROPERTIES FIXTURES_REQUIRED strip_cantilever_np${ranks})
endforeach()
# The same closed forms with each step rebuilding its elements (-output_stresses_cache false) instead
# of applying the operators kept from the first step: both paths, on the strip's two steps.
boltnet_run(strip_cantilever_nocache 2 ${BOLTNET_TEST_SCENES}/strip-cantilever.yaml -output_stresses_cache false)
add_test(NAME strip_cantilever_nocache_stresses_np2
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_stresses.py ${BOLTNET_OUT}/strip_cantilever_nocache_np2
          --length 150 --width 20 --thickness 2 --fz 1000 --fx 2000)
set_tests_properties(strip_cantilever_nocache_stresses_np2 PROPERTIES FIXTURES_REQUIRED strip_cantilever_nocache_np2)
foreach(ranks 2 3)
  add_test(NAME strip_cantilever_fields_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fields.py ${BOLTNET_OUT}/strip_cantilever_np${ranks}
            ${BOLTNET_TEST_SCENES}/strip-cantilever.joints.csv --fixed 0,x,0,all --ref ${BOLTNET_OUT}/strip_cantilever_np1 --rtol 1e-9)
  set_tests_properties(strip_cantilever_fields_np${ranks} PROPERTIES FIXTURES_REQUIRED "strip_cantilever_np1;strip_cantilever_np${ranks}")
endforeach()

# fig3a written by 3 ranks equals 1 rank's (as fig3a_fields_np2 for 2), and meshio reads it.
add_test(NAME fig3a_fields_np3
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fields.py ${BOLTNET_OUT}/fig3a_np3 ${BOLTNET_SCENES}/fig3a.joints.csv ${_fig3a_fixed}
          --ref ${BOLTNET_OUT}/fig3a_np1 --rtol 1e-8)
set_tests_properties(fig3a_fields_np3 PROPERTIES FIXTURES_REQUIRED "fig3a_np1;fig3a_np3")
add_test(NAME fig3a_meshio_np2 COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_meshio.py ${BOLTNET_OUT}/fig3a_np2)
set_tests_properties(fig3a_meshio_np2 PROPERTIES FIXTURES_REQUIRED fig3a_np2)

# A scene name with every character XML escapes (and a tab, which an attribute value keeps only as a
# character reference) still gives valid xdmf files, which meshio and the checker read, and a joint
# table whose scene attribute holds it (odd_name_table). lap-rows on 2 ranks: eight shell parts and
# their joints.
boltnet_run(odd_name 2 ${BOLTNET_SCENES}/lap-rows.yaml -load_steps 3 -output_joints both -scene_name "a<b>&c\"d'e\tf")
add_test(NAME odd_name_fields COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fields.py ${BOLTNET_OUT}/odd_name_np2 ${BOLTNET_SCENES}/lap-rows.joints.csv)
add_test(NAME odd_name_meshio COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_meshio.py ${BOLTNET_OUT}/odd_name_np2)
set_tests_properties(odd_name_fields odd_name_meshio PROPERTIES FIXTURES_REQUIRED odd_name_np2)

# Bypass (bypass.csv): a fastener that carries nothing in a strip in uniform tension passes the whole
# running load (closed form, 1 and 2 ranks); lap-rows' bearing loads are joints.csv's forces, the
# rows follow the force balance, and 2 ranks write what 1 rank writes.
foreach(ranks 1 2)
  boltnet_run(strip_bypass ${ranks} ${BOLTNET_TEST_SCENES}/strip-bypass.yaml -output_bypass_width 30)
  add_test(NAME strip_bypass_np${ranks} COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_bypass.py ${BOLTNET_OUT}/strip_bypass_np${ranks} --uniform 144)
  set_tests_properties(strip_bypass_np${ranks} PROPERTIES FIXTURES_REQUIRED strip_bypass_np${ranks})
endforeach()
add_test(NAME lap_rows_bypass COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_bypass.py ${BOLTNET_OUT}/lap_rows_np2 --ref ${BOLTNET_OUT}/lap_rows_np1)
set_tests_properties(lap_rows_bypass PROPERTIES FIXTURES_REQUIRED "lap_rows_np1;lap_rows_np2")
# lap-rows' sheets are strips as wide as the rivet pitch (20 mm), loaded at one end: with that strip
# width each bypass load is the sum of the bearing loads behind its rivet (a free body of the strip),
# on 1, 2 and 3 ranks, and through fields.h5 on 3. The control: a strip wider than the sheet (24 mm,
# the default of 6 coupling radii) reads the same running loads over 24 mm, and the check fails.
foreach(ranks 1 2 3)
  boltnet_run(lap_rows_strip ${ranks} ${BOLTNET_SCENES}/lap-rows.yaml -output_bypass_width 20)
  add_test(NAME lap_rows_bypass_strip_np${ranks} COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_bypass.py ${BOLTNET_OUT}/lap_rows_strip_np${ranks} --strip ${BOLTNET_SCENES}/lap-rows.joints.csv)
  set_tests_properties(lap_rows_bypass_strip_np${ranks} PROPERTIES FIXTURES_REQUIRED lap_rows_strip_np${ranks})
endforeach()
add_test(NAME lap_rows_bypass_strip_h5 COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_bypass.py ${BOLTNET_OUT}/lap_rows_strip_np3 --h5 --ref ${BOLTNET_OUT}/lap_rows_strip_np1)
set_tests_properties(lap_rows_bypass_strip_h5 PROPERTIES FIXTURES_REQUIRED "lap_rows_strip_np1;lap_rows_strip_np3")
# The sheets cut into patches of at most 200 nodes on 3 ranks, whose bands then hold elements of
# other patches than their rivet's (165 of the candidates, -info): the rows equal the uncut run's.
boltnet_run(lap_rows_strip_cut 3 ${BOLTNET_SCENES}/lap-rows.yaml -output_bypass_width 20 -patch_max_nodes 200)
add_test(NAME lap_rows_bypass_strip_cut_np3 COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_bypass.py ${BOLTNET_OUT}/lap_rows_strip_cut_np3
  --strip ${BOLTNET_SCENES}/lap-rows.joints.csv --ref ${BOLTNET_OUT}/lap_rows_strip_np1)
set_tests_properties(lap_rows_bypass_strip_cut_np3 PROPERTIES FIXTURES_REQUIRED "lap_rows_strip_np1;lap_rows_strip_cut_np3")
add_test(NAME lap_rows_bypass_strip_too_wide COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_bypass.py ${BOLTNET_OUT}/lap_rows_np1 --strip ${BOLTNET_SCENES}/lap-rows.joints.csv)
set_tests_properties(lap_rows_bypass_strip_too_wide PROPERTIES FIXTURES_REQUIRED lap_rows_np1
  PASS_REGULAR_EXPRESSION "FAIL: step 1 joint [0-9]+ on part [0-9]+: bypass [-0-9.e]+, the strip.s balance")
# The same bypass in fields.h5, each rank writing its own joints' rows: the strip's closed form on 1,
# 2 and 3 ranks, and lap-rows on 3 ranks with the joint table in joints.h5, where no bypass.csv is
# written (a model that large gets no table through rank 0), against the 1-rank run's bypass.csv.
boltnet_run(strip_bypass 3 ${BOLTNET_TEST_SCENES}/strip-bypass.yaml -output_bypass_width 30)
foreach(ranks 1 2 3)
  add_test(NAME strip_bypass_h5_np${ranks} COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_bypass.py ${BOLTNET_OUT}/strip_bypass_np${ranks} --uniform 144 --h5)
  set_tests_properties(strip_bypass_h5_np${ranks} PROPERTIES FIXTURES_REQUIRED strip_bypass_np${ranks})
endforeach()
boltnet_run(lap_rows_h5only 3 ${BOLTNET_SCENES}/lap-rows.yaml -output_joints hdf5)
add_test(NAME lap_rows_bypass_h5 COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_bypass.py ${BOLTNET_OUT}/lap_rows_h5only_np3 --h5 --ref ${BOLTNET_OUT}/lap_rows_np1)
set_tests_properties(lap_rows_bypass_h5 PROPERTIES FIXTURES_REQUIRED "lap_rows_np1;lap_rows_h5only_np3")
add_test(NAME lap_rows_h5only_no_bypass_csv COMMAND ${BOLTNET_PYTHON} -c "import os,sys; d=sys.argv[1]; has=os.path.exists(d + '/bypass.csv'); print('bypass.csv written' if has else 'no bypass.csv, as asked'); sys.exit(1 if has or not os.path.exists(d + '/joints.h5') else 0)" ${BOLTNET_OUT}/lap_rows_h5only_np3)
set_tests_properties(lap_rows_h5only_no_bypass_csv PROPERTIES FIXTURES_REQUIRED lap_rows_h5only_np3)

# A footprint named by a node set (the fastener table's column `footprint`, docs/scenes.md): the strip
# cantilever's end edge tied to the load's rigid patch through a joint 50 mm beyond the strip (the
# set's nodes follow it rigidly however far, with -coupling_radius too small to find any), against
# the same closed forms, on 1, 2 and 3 ranks; a set the part lacks and node coupling are refused.
foreach(ranks 1 2 3)
  boltnet_run(strip_tie ${ranks} ${BOLTNET_TEST_SCENES}/strip-cantilever.yaml -scene_joints ${BOLTNET_TEST_SCENES}/strip-tie.joints.csv -coupling_radius 1)
  add_test(NAME strip_tie_stresses_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_stresses.py ${BOLTNET_OUT}/strip_tie_np${ranks}
            --length 150 --width 20 --thickness 2 --fz 1000 --fx 2000)
  set_tests_properties(strip_tie_stresses_np${ranks} PROPERTIES FIXTURES_REQUIRED strip_tie_np${ranks})
endforeach()
set(_tie ${BOLTNET_MPIRUN} 2 --oversubscribe $<TARGET_FILE:boltnet_driver> -output_dir ${BOLTNET_OUT}/bad -scene ${BOLTNET_TEST_SCENES}/strip-cantilever.yaml)
boltnet_expect(bad_tie_no_set 2 ${_bad} --match "Joint 0: its footprint is node set 'tip', which patch 0 does not have"
  -- ${_tie} -scene_joints ${BOLTNET_TEST_SCENES}/tie-noset.joints.csv)
boltnet_expect(bad_tie_node_coupling 2 ${_bad} --match "Joint 0: its footprint is node set 'xmax', which needs -coupling_type exact or penalty"
  -- ${_tie} -scene_joints ${BOLTNET_TEST_SCENES}/strip-tie.joints.csv -coupling_type node)

# A joint's own gap and pretension (the fastener table's columns `gap` and `pretension`,
# docs/scenes.md "Per-joint parameters"): fig3c's joint with 0.03 mm and 8 kN in place of its
# type's 0.05 mm and 10 kN follows fig3c's closed form with j = 0.03 mm and G = mu nf Pc = 2400 N,
# through stick, slide and bearing both ways, on 1, 2 and 3 ranks (with the type's values the same
# check fails at the first slide). A negative gap, a gap on a linear spring and a pretension on the
# contact law are refused, naming the file, line and column.
foreach(ranks 1 2 3)
  boltnet_run(fig3c_own_gap ${ranks} ${BOLTNET_SCENES}/fig3c.yaml -scene_joints ${BOLTNET_TEST_SCENES}/fig3c-gap.joints.csv)
  add_test(NAME fig3c_own_gap_closed_form_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fig3c.py ${BOLTNET_OUT}/fig3c_own_gap_np${ranks}/joints.csv 1.5e5 5000 4e4 0.03 2400)
  set_tests_properties(fig3c_own_gap_closed_form_np${ranks} PROPERTIES FIXTURES_REQUIRED fig3c_own_gap_np${ranks})
endforeach()
set(_own $<TARGET_FILE:boltnet_driver> -output_dir ${BOLTNET_OUT}/bad -scene ${BOLTNET_SCENES}/fig3c.yaml)
boltnet_expect(bad_joint_gap 1 ${_bad} --max-lines 1 --match "fig3c-gap-bad.joints.csv line 3, column 'gap': -0.01 must be a finite number >= 0"
  -- ${_own} -scene_joints ${BOLTNET_TEST_SCENES}/fig3c-gap-bad.joints.csv)
boltnet_expect(bad_joint_gap_spring 1 ${_bad} --max-lines 1 --match "fig3c-gap.joints.csv line 4, column 'gap': joint 0's type 'bolt' is a linear spring, which has no gap"
  -- ${_own} -scene_joints ${BOLTNET_TEST_SCENES}/fig3c-gap.joints.csv -joint_bolt_law spring)
boltnet_expect(bad_joint_pretension_contact 1 ${_bad} --max-lines 1 --match "column 'pretension': joint 0's type 'bolt' is not of the frictional law"
  -- ${_own} -scene_joints ${BOLTNET_TEST_SCENES}/fig3c-gap.joints.csv -joint_bolt_law contact)
