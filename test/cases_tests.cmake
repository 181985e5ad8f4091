# Load cases on one set-up (docs/scenes.md, "Load cases"; docs/nastran.md for a deck's subcases).
# Included by test/CMakeLists.txt (boltnet_run, boltnet_expect, _bad, _run) after
# nastran_model_tests.cmake (boltnet_deck_run, the decks of scripts/make-nastran-strips).
#
# A case of a multi-case run shares its set-up with the other cases; the reference for it is the
# same scene run with that case alone (-load_cases <case>, -nastran_subcase <id>), which sets the
# model up for that case's loads only. test/compare_case.py compares joints.csv and every dataset of
# fields.h5 (1e-10 of each quantity's scale).

# boltnet_compare_case(NAME CASE RANKS MULTI ALONE [OTHER...]): the case folder of the run MULTI
# against ALONE's; the quantities' scales are also taken over MULTI's other cases OTHER (a jump that
# a pure moment leaves at zero is judged against the jumps of the run, not its own round-off).
function(boltnet_compare_case name case ranks multi alone)
  set(_scales)
  foreach(other ${ARGN})
    list(APPEND _scales --scale-from ${BOLTNET_OUT}/${multi}_np${ranks}/${other})
  endforeach()
  add_test(NAME ${name}_${case}_same_as_alone_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_case.py ${BOLTNET_OUT}/${alone}_np${ranks}/${case} ${BOLTNET_OUT}/${multi}_np${ranks}/${case} --rtol 1e-10 ${_scales})
  set_tests_properties(${name}_${case}_same_as_alone_np${ranks} PROPERTIES FIXTURES_REQUIRED "${multi}_np${ranks};${alone}_np${ranks}")
endfunction()

foreach(ranks 1 2 3)
  # The strip: tension, bending and bending with its own path (through -1000) on one set-up
  # (requirement: several cases per run, each with the usual outputs; a case against a closed form):
  # every node of every step of each case against the exact constant-strain and constant-curvature
  # solutions (check_strip.py, rtol 1e-8 as test/triangle_tests.cmake's strips), and each case
  # against a run of it alone (requirement: the same results as a separate single-case run).
  boltnet_run(strip_cases ${ranks} ${BOLTNET_TEST_SCENES}/strip-cases.yaml)
  foreach(case_load "tension;tension" "bending;bending" "bending-back;bending")
    list(GET case_load 0 case)
    list(GET case_load 1 load)
    add_test(NAME strip_cases_${case}_exact_np${ranks}
      COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_strip.py ${BOLTNET_OUT}/strip_cases_np${ranks}/${case} ${load} 72000 20 1.27 1e-8)
    set_tests_properties(strip_cases_${case}_exact_np${ranks} PROPERTIES FIXTURES_REQUIRED strip_cases_np${ranks})
    boltnet_run(strip_case_${case} ${ranks} ${BOLTNET_TEST_SCENES}/strip-cases.yaml -load_cases ${case})
    boltnet_compare_case(strip_cases ${case} ${ranks} strip_cases strip_case_${case} tension bending bending-back)
  endforeach()

  # The riveted laps: pull and push prescribe other values on the same dof inside the condensed
  # patches (one set-up, new load terms from the kept factorisations); tug holds other dof (a set-up
  # of its own). Each case against a run of it alone.
  boltnet_run(lap_cases ${ranks} ${BOLTNET_TEST_SCENES}/lap-cases.yaml)
  foreach(case pull push tug)
    boltnet_run(lap_case_${case} ${ranks} ${BOLTNET_TEST_SCENES}/lap-cases.yaml -load_cases ${case})
    boltnet_compare_case(lap_cases ${case} ${ranks} lap_cases lap_case_${case} pull push tug)
  endforeach()

  # The joint history is reset between cases (requirement): after fig3c's cycle, which leaves the
  # joint with a slip of -0.119 mm at zero load, the case after (a pull past the friction threshold)
  # gives what it gives alone; without the reset its first rows differ (stick against contact). The
  # cycle itself against fig3c's closed form (check_fig3c.py).
  boltnet_run(fig3c_cases ${ranks} ${BOLTNET_TEST_SCENES}/fig3c-cases.yaml)
  boltnet_run(fig3c_case_after ${ranks} ${BOLTNET_TEST_SCENES}/fig3c-cases.yaml -load_cases after)
  boltnet_compare_case(fig3c_cases after ${ranks} fig3c_cases fig3c_case_after cycle)
  add_test(NAME fig3c_cases_cycle_closed_form_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fig3c.py ${BOLTNET_OUT}/fig3c_cases_np${ranks}/cycle/joints.csv 1.5e5 5000 4e4 0.05 3000)
  set_tests_properties(fig3c_cases_cycle_closed_form_np${ranks} PROPERTIES FIXTURES_REQUIRED fig3c_cases_np${ranks})

  # A deck's subcases: 1 and 2 share SPC set 1 (one set-up), 3 has SPC set 2 (a set-up of its own).
  # Each against the exact solution and against a run of that subcase alone.
  boltnet_deck_run(nastran_cases ${ranks} ${_nm}/strip-spc.bdf -load_max 1 -load_steps 1)
  foreach(sub_load "1;tension" "2;bending" "3;tension")
    list(GET sub_load 0 sub)
    list(GET sub_load 1 load)
    add_test(NAME nastran_cases_${sub}_exact_np${ranks}
      COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_strip.py ${BOLTNET_OUT}/nastran_cases_np${ranks}/subcase-${sub} ${load} 72000 20 1.27 1e-8)
    set_tests_properties(nastran_cases_${sub}_exact_np${ranks} PROPERTIES FIXTURES_REQUIRED nastran_cases_np${ranks})
    boltnet_deck_run(nastran_case_${sub} ${ranks} ${_nm}/strip-spc.bdf -load_max 1 -load_steps 1 -nastran_subcase ${sub})
    boltnet_compare_case(nastran_cases subcase-${sub} ${ranks} nastran_cases nastran_case_${sub} subcase-1 subcase-2 subcase-3)
  endforeach()
endforeach()

# What the runs say: the set-ups and their cases, one summary line per case.
add_test(NAME lap_cases_setups
  COMMAND ${BOLTNET_EXPECT} --match "set-up 1 of 2 \\([0-9.]+ s\\) for 2 load case\\(s\\): pull, push" --match "set-up 2 of 2 \\([0-9.]+ s\\) for 1 load case\\(s\\): tug"
          --match "3 load cases on 2 set-up\\(s\\)" --match "case push: converged, 1 steps"
          -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/lap-cases.yaml -output_dir ${BOLTNET_OUT}/lap_cases_setups -load_progress false)
set_tests_properties(lap_cases_setups PROPERTIES ENVIRONMENT "${BOLTNET_ENV}")
add_test(NAME nastran_cases_setups
  COMMAND ${BOLTNET_EXPECT} --match "set-up 1 of 2 \\([0-9.]+ s\\) for 2 load case\\(s\\): subcase-1, subcase-2" --match "set-up 2 of 2 \\([0-9.]+ s\\) for 1 load case\\(s\\): subcase-3"
          -- $<TARGET_FILE:boltnet_driver> -nastran_deck ${_nm}/strip-spc.bdf -output_dir ${BOLTNET_OUT}/nastran_cases_setups -load_max 1 -load_steps 1)
set_tests_properties(nastran_cases_setups PROPERTIES ENVIRONMENT "${BOLTNET_ENV}" FIXTURES_REQUIRED nastran_strips)

# Bad input (requirement): one line naming the option, exit 1, nothing written.
set(_cs ${BOLTNET_TEST_SCENES}/strip-cases.yaml)
set(_one --max-lines 1)
boltnet_expect(bad_case_undefined_load 2 ${_bad} --absent ${BOLTNET_OUT}/bad/tension
  --match "Load case 'tension' \\(-load_case_tension_loads\\): load 'pull' is not in the column 'load' of .*strip-cases.bcs.csv \\(its loads: bending, tension\\)"
  -- ${_run} -scene ${_cs} -load_case_tension_loads pull)
boltnet_expect(bad_case_duplicate 1 ${_bad} ${_one} --match "-load_cases: the case 'bending' is named twice"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_cs} -output_dir ${BOLTNET_OUT}/bad -load_cases bending,tension,bending)
boltnet_expect(bad_case_empty_list 1 ${_bad} ${_one} --match "-load_cases is empty: name at least one load case"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_cs} -output_dir ${BOLTNET_OUT}/bad -load_cases)
boltnet_expect(bad_case_empty_yaml 1 ${_bad} ${_one} --match "empty-cases.yaml line 14, column 10: 'cases' is an empty list, which sets no option"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/empty-cases.yaml -output_dir ${BOLTNET_OUT}/bad)
boltnet_expect(bad_case_name 1 ${_bad} ${_one} --match "-load_cases: 'Bend' is not a load case name"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_cs} -output_dir ${BOLTNET_OUT}/bad -load_cases tension,Bend)
boltnet_expect(bad_case_no_loads 2 ${_bad} --match "Load case 'shear' names no load: give -load_case_shear_loads"
  -- ${_run} -scene ${_cs} -load_cases tension,shear)
boltnet_expect(bad_case_misspelled_option 1 ${_bad} ${_one} --match "Unknown boltnet option\\(s\\): -load_case_tension_lods"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_cs} -output_dir ${BOLTNET_OUT}/bad -load_case_tension_lods tension)
boltnet_expect(bad_case_load_name 1 ${_bad} ${_one} --match "bad-load.bcs.csv line 3, column 'load': 'Pull' is not a load name"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_cs} -output_dir ${BOLTNET_OUT}/bad -scene_bcs ${BOLTNET_TEST_SCENES}/bad-load.bcs.csv)
boltnet_expect(bad_case_not_listed 1 ${_bad} ${_one} --match "The options define load case 'pull' \\(-load_case_pull_loads\\) but -load_cases lists no case"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/bad -load_case_pull_loads pull)
boltnet_expect(bad_case_checkpoint 1 ${_bad} ${_one} --match "-checkpoint_every and -restart are not available with -load_cases"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_cs} -output_dir ${BOLTNET_OUT}/bad -checkpoint_every 1)
boltnet_expect(bad_case_with_deck 1 ${_bad} ${_one} --match "-load_cases is for a scene's tables: a Nastran deck's load cases are its subcases"
  -- $<TARGET_FILE:boltnet_driver> -nastran_deck ${_nm}/strip.bdf -output_dir ${BOLTNET_OUT}/bad -load_cases tension)
set_tests_properties(bad_case_with_deck_np1 PROPERTIES FIXTURES_REQUIRED nastran_strips)

# A case that fails does not stop the others, which start unloaded as usual: with at most three
# Newton iterations per step and no cut-back, fig3c's cycle in one step per segment reaches 6 kN
# (the joint slid and bears) and fails on the way back (summary.json "failed"); the case after
# converges and gives what it gives alone; the run exits 3.
foreach(ranks 1 2)
  set(_strict -load_progress false -load_case_cycle_steps 1 -snes_max_it 3 -load_max_cuts 0)
  boltnet_expect(fig3c_cases_failed ${ranks} --fail --match "case cycle: FAILED at load factor 6000 after 1 steps" --match "case after: converged, 45 steps"
    -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/fig3c-cases.yaml -output_dir ${BOLTNET_OUT}/fig3c_cases_failed_np${ranks} ${_strict})
  set_tests_properties(fig3c_cases_failed_np${ranks} PROPERTIES FIXTURES_SETUP fig3c_cases_failed_np${ranks})
  boltnet_run(fig3c_case_after_strict ${ranks} ${BOLTNET_TEST_SCENES}/fig3c-cases.yaml -load_cases after ${_strict})
  boltnet_compare_case(fig3c_cases_failed after ${ranks} fig3c_cases_failed fig3c_case_after_strict)
endforeach()

# Held loads (docs/scenes.md, "Held loads"): a case that continues the one before it starts from
# its end, its loads held, and applies its own loads on top. Each against a closed form:
# - the strip: tension to 1000 N, then bending to 1000 and back to -1000 N mm with the tension held:
#   at every step the sum of the two exact solutions (check_strip.py --held), condensed and not;
# - fig3c's frictional joint: 2000 N along x held while fig3c's cycle is added along x: its closed
#   form with the force offset by 2000 N, stick, slide and bearing both ways (check_fig3c.py
#   --held); and pushed along y across the held 2000 N: stick up to the isotropic cone's
#   sqrt(G^2 - 2000^2) = 2236 N, slide on the cone beyond (check_held_cone.py).
foreach(ranks 1 2 3)
  boltnet_run(strip_held ${ranks} ${BOLTNET_TEST_SCENES}/strip-held.yaml)
  add_test(NAME strip_held_exact_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_strip.py ${BOLTNET_OUT}/strip_held_np${ranks}/bending bending 72000 20 1.27 1e-8 --held tension=1000)
  set_tests_properties(strip_held_exact_np${ranks} PROPERTIES FIXTURES_REQUIRED strip_held_np${ranks})
  boltnet_run(fig3c_held ${ranks} ${BOLTNET_TEST_SCENES}/fig3c-held.yaml)
  add_test(NAME fig3c_held_cycle_closed_form_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_fig3c.py ${BOLTNET_OUT}/fig3c_held_np${ranks}/cycle/joints.csv 1.5e5 5000 4e4 0.05 3000 --held 2000)
  set_tests_properties(fig3c_held_cycle_closed_form_np${ranks} PROPERTIES FIXTURES_REQUIRED fig3c_held_np${ranks})
  boltnet_run(fig3c_held_across ${ranks} ${BOLTNET_TEST_SCENES}/fig3c-held.yaml -load_cases preload,across)
  add_test(NAME fig3c_held_across_cone_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_held_cone.py ${BOLTNET_OUT}/fig3c_held_across_np${ranks}/across/joints.csv 2000 1.5e5 5000 3000)
  set_tests_properties(fig3c_held_across_cone_np${ranks} PROPERTIES FIXTURES_REQUIRED fig3c_held_across_np${ranks})
endforeach()
boltnet_run(strip_held_uncondensed 1 ${BOLTNET_TEST_SCENES}/strip-held.yaml -patch_condense false)
add_test(NAME strip_held_uncondensed_exact
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_strip.py ${BOLTNET_OUT}/strip_held_uncondensed_np1/bending bending 72000 20 1.27 1e-8 --held tension=1000)
set_tests_properties(strip_held_uncondensed_exact PROPERTIES FIXTURES_REQUIRED strip_held_uncondensed_np1)

# A case whose case before failed is not run: its summary.json says why, the run exits 3 (preload
# pushed past G with one Newton iteration per step and no cut-back).
boltnet_expect(fig3c_held_after_failure 1 --fail --match "case cycle not run: the case it continues, preload, did not converge"
  --match "case preload: FAILED at load factor 0"
  -- $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_TEST_SCENES}/fig3c-held.yaml -output_dir ${BOLTNET_OUT}/fig3c_held_after_failure
     -load_progress false -load_case_preload_max 7000 -snes_max_it 1 -load_max_cuts 0)
add_test(NAME fig3c_held_after_failure_summary
  COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); sys.exit(0 if s['status']=='failed' and s['continues']=='preload' and s['steps']==0 and 'did not converge' in s['message'] else 1)"
          ${BOLTNET_OUT}/fig3c_held_after_failure/cycle/summary.json)
set_tests_properties(fig3c_held_after_failure_summary PROPERTIES DEPENDS fig3c_held_after_failure_np1)

# Bad input: a continued case that does not come just before, or that holds other dof; a case
# continuing itself.
set(_fh ${BOLTNET_TEST_SCENES}/fig3c-held.yaml)
boltnet_expect(bad_held_order 1 ${_bad} ${_one} --match "Load case 'cycle' \\(-load_case_cycle_continues preload\\): the case it continues must be run just before it: 'preload' must come right before 'cycle' in -load_cases"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_fh} -output_dir ${BOLTNET_OUT}/bad -load_cases cycle,preload)
boltnet_expect(bad_held_alone 1 ${_bad} ${_one} --match "'preload' must come right before 'cycle' in -load_cases"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_fh} -output_dir ${BOLTNET_OUT}/bad -load_cases cycle)
boltnet_expect(bad_held_itself 1 ${_bad} ${_one} --match "Load case 'across' \\(-load_case_across_continues\\): a case cannot continue itself"
  -- $<TARGET_FILE:boltnet_driver> -scene ${_fh} -output_dir ${BOLTNET_OUT}/bad -load_case_across_continues across)
boltnet_expect(bad_held_other_dof 2 ${_bad} --match "Load case 'grip' \\(-load_case_grip_continues preload\\) fixes or prescribes other dof than 'preload'"
  -- ${_run} -scene ${_fh} -scene_bcs ${BOLTNET_TEST_SCENES}/held-other-dof.bcs.csv -load_cases preload,grip -load_case_grip_loads grip -load_case_grip_continues preload)
