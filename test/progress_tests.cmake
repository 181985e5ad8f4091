# The progress line of the driver (-load_progress, docs/scenes.md "Progress"). Included from
# test/CMakeLists.txt (BOLTNET_PYTHON, BOLTNET_ENV).
#
# Requirement: one line per converged step with the step of the total nominal steps (every segment
# of the load path counted; a cut-back shown as the part of the step reached and the halvings), the
# load, the Newton iterations, the joints sticking, sliding and bearing summed over ranks, the
# elapsed time and an estimate of the time left. check_progress.py compares every line with what
# the run wrote by other paths (summary.json: steps, Newton iterations, cut-backs; joints.csv: load,
# states and bearing of every joint, gathered to rank 0) and with the nominal step count of the
# scene's path, given here: segments x -load_steps.

# The arithmetic of the line (nominal step of the path, part of it, time left) against closed forms.
add_executable(test_progress test_progress.cpp ${PROJECT_SOURCE_DIR}/lib/solver/progress.cpp ${PROJECT_SOURCE_DIR}/lib/solver/loadpath.cpp)
target_include_directories(test_progress PRIVATE ${PROJECT_SOURCE_DIR}/lib)
target_link_libraries(test_progress PRIVATE GTest::gtest GTest::gtest_main PkgConfig::PETSC MPI::MPI_C)
gtest_discover_tests(test_progress)

# progress_test(NAME RANKS SCENE NOMINAL ARGS...): run the driver, its output to a file, and check it.
function(progress_test name ranks scene nominal)
  set(out ${BOLTNET_OUT}/progress_${name}_np${ranks})
  add_test(NAME progress_${name}_np${ranks}
    COMMAND sh -c "rm -rf \"$4\" && \"$0\" -n $1 --oversubscribe \"$2\" -scene \"$3\" -output_dir \"$4\" -output_fields false \"$@\" > \"$4.txt\" 2>&1; rc=$?; cat \"$4.txt\"; [ $rc = 0 ] && ${BOLTNET_PYTHON} \"$5\" \"$4.txt\" \"$4/summary.json\" \"$4/joints.csv\" $6"
            ${MPIEXEC_EXECUTABLE} ${ranks} $<TARGET_FILE:boltnet_driver> ${scene} ${out} ${CMAKE_CURRENT_SOURCE_DIR}/check_progress.py ${nominal} ${ARGN})
  set_tests_properties(progress_${name}_np${ranks} PROPERTIES PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}")
endfunction()

foreach(ranks 1 2)
  # fig3c as shipped: a table of 3 segments (6000, -6000, 0) of 60 steps; the one joint sticks,
  # slides, bears, and does it again the other way.
  progress_test(fig3c ${ranks} ${BOLTNET_SCENES}/fig3c.yaml 180)
  # Cut-backs: with 3 steps per segment and 2 Newton iterations per solve, the steps in which the
  # joint goes from stick through sliding into bearing are cut back (7 halvings, 27 converged steps
  # for the 9 nominal ones) and reached by sub-steps. Without the secant predictor: with it, the
  # 2 iterations suffice and nothing is cut back.
  progress_test(fig3c_cutbacks ${ranks} ${BOLTNET_SCENES}/fig3c.yaml 9 -load_steps 3 -snes_max_it 2 -load_predictor false)
endforeach()
foreach(ranks 1 2 3)
  # fig3b: four contact joints on shell parts cut into patches over the ranks, bearing in turn
  # (2, 3, 3, 4 over the first four steps): the counts are sums over the ranks' own joints.
  progress_test(fig3b ${ranks} ${BOLTNET_SCENES}/fig3b.yaml 10 -load_steps 10)
endforeach()
# The cut-back run must have cut back (else it checks nothing of the sub-step lines).
add_test(NAME progress_fig3c_cutbacks_cut_back
  COMMAND ${BOLTNET_PYTHON} -c "import json, sys; s = json.load(open(sys.argv[1])); print('cut-backs:', s['cutbacks']); sys.exit(s['cutbacks'] == 0)"
          ${BOLTNET_OUT}/progress_fig3c_cutbacks_np1/summary.json)
set_tests_properties(progress_fig3c_cutbacks_cut_back PROPERTIES DEPENDS progress_fig3c_cutbacks_np1)

# Quiet: with -load_progress false, fig3c in 2 steps per segment prints its first line, the line of
# converged steps and that of the most loaded joint, and no progress line (6 more with it).
boltnet_expect(progress_quiet 1 --max-lines 3 --match "6 steps converged" --
  $<TARGET_FILE:boltnet_driver> -scene ${BOLTNET_SCENES}/fig3c.yaml -output_dir ${BOLTNET_OUT}/progress_quiet
  -load_steps 2 -load_progress false)
