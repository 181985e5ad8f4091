# The wing-fuselage junction (scripts/make-wing-fuselage, docs/wing-fuselage.md): the tiny size,
# generated here, through the driver on 1, 2 and 3 ranks, against independent checks.
set(_wf ${BOLTNET_OUT}/wing)
set(_wfgen ${BOLTNET_PYTHON} ${PROJECT_SOURCE_DIR}/scripts/make-wing-fuselage)
# The checks below measure the model against independent references to 1e-6 and finer, so they need
# the solve to round-off: they run the global factorisation (-patch_condense false). Every patch
# condensed (-patch_condense true) balances this scene only to about 1.5e-5 of the tip load (the
# cancellation in S over the spar and rib patches' many ports, docs/solver.md); the default
# condenses only the patches of few ports for their size (ratio 4), and must give the global
# factorisation's joints and the same balance (wing_tiny_condensed).
set(_exact -patch_condense false)

# wing_tiny_balanced(NAME GENERATOR-ARGS...): the tiny junction NAME generated with the arguments,
# run on 1, 2 and 3 ranks. Each outer box is held only by the side-of-body fasteners: they balance its
# tip load at every step (check_junction_equilibrium.py says why 1e-6).
function(wing_tiny_balanced name)
  add_test(NAME wing_make_${name} COMMAND ${_wfgen} ${_wf} ${name} --size tiny --load-steps 2 ${ARGN})
  set_tests_properties(wing_make_${name} PROPERTIES FIXTURES_SETUP wing_${name}_scene)
  foreach(ranks 1 2 3)
    boltnet_run(wing_${name} ${ranks} ${_wf}/${name}.yaml ${_exact})
    set_tests_properties(run_wing_${name}_np${ranks} PROPERTIES FIXTURES_REQUIRED wing_${name}_scene)
    add_test(NAME wing_${name}_equilibrium_np${ranks}
      COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_equilibrium.py ${BOLTNET_OUT}/wing_${name}_np${ranks} ${_wf}/${name}.yaml 1e-6)
    set_tests_properties(wing_${name}_equilibrium_np${ranks} PROPERTIES FIXTURES_REQUIRED "wing_${name}_scene;wing_${name}_np${ranks}")
  endforeach()
endfunction()

# The frictional scene along its load path (1 g, 2.5 g, -1 g, 0; two steps per segment).
wing_tiny_balanced(tiny)
# Each fastener's own drawn clearance (the fastener table's column gap) is the one its law used: it
# bears exactly when its slip exceeds that gap, at every step (check_own_gaps.py), on 1, 2 and 3 ranks.
foreach(ranks 1 2 3)
  add_test(NAME wing_tiny_own_gaps_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_own_gaps.py ${BOLTNET_OUT}/wing_tiny_np${ranks} ${_wf}/tiny.joints.csv)
  set_tests_properties(wing_tiny_own_gaps_np${ranks} PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_np${ranks}")
endforeach()
# The bypass strip's width comes from the scene's output: section (the skin splices' pitch along a
# row), read after the scene's options, and the command line still wins (check_junction_bypass.py).
add_test(NAME wing_tiny_bypass_width
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_bypass.py ${BOLTNET_OUT}/wing_tiny_np1 ${_wf}/tiny.yaml)
set_tests_properties(wing_tiny_bypass_width PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_np1")
boltnet_expect(wing_tiny_bypass_width_given 1 --match "steps converged" --
  $<TARGET_FILE:boltnet_driver> -scene ${_wf}/tiny.yaml -output_dir ${BOLTNET_OUT}/wing_tiny_bypass_given
  -load_table 1 -load_steps 1 -output_bypass_width 150)
set_tests_properties(wing_tiny_bypass_width_given_np1 PROPERTIES FIXTURES_REQUIRED wing_tiny_scene FIXTURES_SETUP wing_tiny_bypass_given)
add_test(NAME wing_tiny_bypass_width_given_check
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_bypass.py ${BOLTNET_OUT}/wing_tiny_bypass_given ${_wf}/tiny.yaml 150)
set_tests_properties(wing_tiny_bypass_width_given_check PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_bypass_given")
# The joint table joints.h5 in place of joints.csv (as from 10,000 joints): the equilibrium check
# reads it the same way, 2 ranks.
boltnet_run(wing_tiny_h5 2 ${_wf}/tiny.yaml ${_exact} -output_joints hdf5)
set_tests_properties(run_wing_tiny_h5_np2 PROPERTIES FIXTURES_REQUIRED wing_tiny_scene)
add_test(NAME wing_tiny_h5_equilibrium
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_equilibrium.py ${BOLTNET_OUT}/wing_tiny_h5_np2 ${_wf}/tiny.yaml 1e-6)
set_tests_properties(wing_tiny_h5_equilibrium PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_h5_np2")
# With joints.h5 there is no bypass.csv: the bypass chart reads fields.h5, and its loads are numbers.
add_test(NAME wing_tiny_plot_h5
  COMMAND sh -c "${BOLTNET_PYTHON} \"$0\" \"$1\" \"$2\" -o \"$3\" > \"$3.log\" 2>&1; s=$?; cat \"$3.log\"; test $s = 0 && test ! -e \"$1/bypass.csv\" && test -s \"$3/bypass.png\" && ! grep -q 'bypass' \"$3.log\""
          ${PROJECT_SOURCE_DIR}/scripts/plot-junction.py ${BOLTNET_OUT}/wing_tiny_h5_np2 ${_wf}/tiny.yaml ${BOLTNET_OUT}/wing_tiny_charts_h5)
set_tests_properties(wing_tiny_plot_h5 PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_h5_np2")
# Results do not depend on the number of ranks (standards).
boltnet_compare_ranks(wing_tiny 1e-8 2)
boltnet_run(wing_tiny_condensed 2 ${_wf}/tiny.yaml)
set_tests_properties(run_wing_tiny_condensed_np2 PROPERTIES FIXTURES_REQUIRED wing_tiny_scene)
add_test(NAME wing_tiny_condensed_vs_global
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/wing_tiny_np1/joints.csv ${BOLTNET_OUT}/wing_tiny_condensed_np2/joints.csv 1e-8)
set_tests_properties(wing_tiny_condensed_vs_global PROPERTIES FIXTURES_REQUIRED "wing_tiny_np1;wing_tiny_condensed_np2")
add_test(NAME wing_tiny_condensed_equilibrium
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_equilibrium.py ${BOLTNET_OUT}/wing_tiny_condensed_np2 ${_wf}/tiny.yaml 1e-6)
set_tests_properties(wing_tiny_condensed_equilibrium PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_condensed_np2")
add_test(NAME wing_tiny_condensed_some
  COMMAND ${BOLTNET_PYTHON} -c "import json,sys; s=json.load(open(sys.argv[1])); print(s['condensed_patches'], 'of', s['patches'], 'patches condensed'); sys.exit(0 if 0 < s['condensed_patches'] < s['patches'] else 1)"
          ${BOLTNET_OUT}/wing_tiny_condensed_np2/summary.json)
set_tests_properties(wing_tiny_condensed_some PROPERTIES FIXTURES_REQUIRED wing_tiny_condensed_np2)
# The generator's spring stiffnesses are boltnet's identification of the same fasteners.
add_test(NAME wing_tiny_springs_vs_identify
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_springs.py $<TARGET_FILE:boltnet_identify> ${_wf}/tiny.yaml)
set_tests_properties(wing_tiny_springs_vs_identify PROPERTIES FIXTURES_REQUIRED wing_tiny_scene)
# The load-transfer charts read the run and the metadata.
add_test(NAME wing_tiny_plot
  COMMAND sh -c "${BOLTNET_PYTHON} \"$0\" \"$1\" \"$2\" -o \"$3\" --compare \"$4\" && for f in load-transfer.png row-share.png states.png most-loaded.csv most-loaded.png junction.png hysteresis.png bypass.png springs.csv; do test -s \"$3/$f\" || { echo \"$f not written\"; exit 1; }; done"
          ${PROJECT_SOURCE_DIR}/scripts/plot-junction.py ${BOLTNET_OUT}/wing_tiny_np1 ${_wf}/tiny.yaml ${BOLTNET_OUT}/wing_tiny_charts
          ${BOLTNET_OUT}/wing_tiny_linear_np1)
set_tests_properties(wing_tiny_plot PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_np1;wing_tiny_linear_np1" FIXTURES_SETUP wing_tiny_charts)
# springs.csv, the frictional run against the linear springs: its columns hold together; and the
# linear run compared with itself gives every ratio 1 and the same shares, maxima and neighbour
# differences on both sides (check_springs_table.py).
add_test(NAME wing_tiny_springs_table COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_springs_table.py ${BOLTNET_OUT}/wing_tiny_charts/springs.csv)
set_tests_properties(wing_tiny_springs_table PROPERTIES FIXTURES_REQUIRED wing_tiny_charts)
add_test(NAME wing_tiny_springs_table_same
  COMMAND sh -c "${BOLTNET_PYTHON} \"$0\" \"$1\" \"$2\" -o \"$3\" --compare \"$1\" --levels 1 && ${BOLTNET_PYTHON} \"$4\" \"$3/springs.csv\" --same"
          ${PROJECT_SOURCE_DIR}/scripts/plot-junction.py ${BOLTNET_OUT}/wing_tiny_linear_np1 ${_wf}/tiny.yaml ${BOLTNET_OUT}/wing_tiny_charts_same
          ${CMAKE_CURRENT_SOURCE_DIR}/check_springs_table.py)
set_tests_properties(wing_tiny_springs_table_same PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_linear_np1")

# Every fastener a linear spring (the scene's override file): the half model against the model of
# both wings, mirror-symmetric loads (check_junction_symmetry.py). The half model runs at the
# tiny scene's 1 g load; the both-sides model on 2 ranks. Both take each element's own normals
# (-shell_directors false): a node of the fuselage on the symmetry plane averages the normals of the
# elements on one side only in the half model and of both sides in the whole one, so with averaged
# directors the two are not the same discrete model (they differ by 6e-8 of the largest force).
add_test(NAME wing_make_tiny_both COMMAND ${_wfgen} ${_wf} tiny-both --size tiny --both-sides)
set_tests_properties(wing_make_tiny_both PROPERTIES FIXTURES_SETUP wing_tiny_both_scene)
boltnet_run(wing_tiny_linear 1 ${_wf}/tiny.yaml -options_file ${_wf}/tiny.linear.opts -load_table 1 -load_steps 1 -shell_directors false ${_exact})
set_tests_properties(run_wing_tiny_linear_np1 PROPERTIES FIXTURES_REQUIRED wing_tiny_scene)
boltnet_run(wing_tiny_both_linear 2 ${_wf}/tiny-both.yaml -options_file ${_wf}/tiny-both.linear.opts -load_table 1 -load_steps 1 -shell_directors false ${_exact})
set_tests_properties(run_wing_tiny_both_linear_np2 PROPERTIES FIXTURES_REQUIRED wing_tiny_both_scene)
add_test(NAME wing_tiny_symmetry
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_symmetry.py ${BOLTNET_OUT}/wing_tiny_linear_np1 ${_wf}/tiny.yaml
          ${BOLTNET_OUT}/wing_tiny_both_linear_np2 ${_wf}/tiny-both.yaml 1e-9)
set_tests_properties(wing_tiny_symmetry PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_both_scene;wing_tiny_linear_np1;wing_tiny_both_linear_np2")
add_test(NAME wing_tiny_both_equilibrium
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_equilibrium.py ${BOLTNET_OUT}/wing_tiny_both_linear_np2 ${_wf}/tiny-both.yaml 1e-6)
set_tests_properties(wing_tiny_both_equilibrium PROPERTIES FIXTURES_REQUIRED "wing_tiny_both_scene;wing_tiny_both_linear_np2")
# Every part but the fuselage as one free body: both wings' tip loads against what holds the wing box,
# the lap on the tee's stems and the spar frames' fasteners alone.
add_test(NAME wing_tiny_both_whole_box_equilibrium
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_equilibrium.py ${BOLTNET_OUT}/wing_tiny_both_linear_np2 ${_wf}/tiny-both.yaml 1e-6 --whole-box)
set_tests_properties(wing_tiny_both_whole_box_equilibrium PROPERTIES FIXTURES_REQUIRED "wing_tiny_both_scene;wing_tiny_both_linear_np2")

# Beam theory (check_junction_beam.py): the small size under a pure bending moment, linear springs,
# with aluminium outer skins and with carbon-epoxy ones (laminate sections, fasteners identified
# with Huth's graphite-epoxy constant). Its tolerances are percent: the default (condensed) solve.
foreach(skin aluminium cfrp)
  add_test(NAME wing_make_small_moment_${skin} COMMAND ${_wfgen} ${_wf} small-moment-${skin} --size small --outer-skin ${skin}
                                                       --shear 0 --torque 0 --load-scale 1 --load-table 1 --load-steps 1)
  set_tests_properties(wing_make_small_moment_${skin} PROPERTIES FIXTURES_SETUP wing_small_moment_${skin}_scene)
  boltnet_run(wing_small_moment_${skin} 1 ${_wf}/small-moment-${skin}.yaml -options_file ${_wf}/small-moment-${skin}.linear.opts)
  set_tests_properties(run_wing_small_moment_${skin}_np1 PROPERTIES FIXTURES_REQUIRED wing_small_moment_${skin}_scene)
  add_test(NAME wing_small_beam_${skin}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_beam.py ${BOLTNET_OUT}/wing_small_moment_${skin}_np1 ${_wf}/small-moment-${skin}.yaml)
  set_tests_properties(wing_small_beam_${skin} PROPERTIES FIXTURES_REQUIRED "wing_small_moment_${skin}_scene;wing_small_moment_${skin}_np1")
  # Under the pure moment each skin splice's rows share the load as the spring chain of
  # docs/lap-rows.md says, in the middle half of the chord (check_junction_chain.py).
  add_test(NAME wing_small_chain_${skin}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_chain.py ${BOLTNET_OUT}/wing_small_moment_${skin}_np1 ${_wf}/small-moment-${skin}.yaml)
  set_tests_properties(wing_small_chain_${skin} PROPERTIES FIXTURES_REQUIRED "wing_small_moment_${skin}_scene;wing_small_moment_${skin}_np1")
  # The bypass loads beside the skins' fasteners against the free body of a strip of skin from the
  # butt: the sum of the bearing loads of the rows nearer the butt (check_junction_strip.py).
  add_test(NAME wing_small_strip_${skin}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_strip.py ${BOLTNET_OUT}/wing_small_moment_${skin}_np1 ${_wf}/small-moment-${skin}.yaml)
  set_tests_properties(wing_small_strip_${skin} PROPERTIES FIXTURES_REQUIRED "wing_small_moment_${skin}_scene;wing_small_moment_${skin}_np1")
endforeach()
# The control: bands 100 mm long reach over the next rows' footprints, whose coupling forces enter
# them, and the same check fails (measured 35 % of the strip's load off).
boltnet_run(wing_small_moment_long_bands 1 ${_wf}/small-moment-aluminium.yaml -options_file ${_wf}/small-moment-aluminium.linear.opts -output_bypass_length 100)
set_tests_properties(run_wing_small_moment_long_bands_np1 PROPERTIES FIXTURES_REQUIRED wing_small_moment_aluminium_scene)
add_test(NAME wing_small_strip_long_bands
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_strip.py ${BOLTNET_OUT}/wing_small_moment_long_bands_np1 ${_wf}/small-moment-aluminium.yaml)
set_tests_properties(wing_small_strip_long_bands PROPERTIES FIXTURES_REQUIRED "wing_small_moment_aluminium_scene;wing_small_moment_long_bands_np1"
  PASS_REGULAR_EXPRESSION "largest difference 0\\.[1-9][0-9]* of the strip's load.*check_junction_strip: FAIL")

# The small size, the scene as generated (friction, clearances, bearing), along its load path (1 g,
# 2.5 g, -1 g, 0; one step per segment) on 1 and 2 ranks with the global factorisation: each outer
# box balanced by its side-of-body fasteners at every step (check_junction_equilibrium.py) and the
# same joints on 2 ranks; the default solve (patches condensed where they have few ports for their
# size) gives the global factorisation's joints. Then every fastener a linear spring
# (small.linear.opts), the default solve on 1 rank against the global factorisation on 2, an
# independent linear solve of the same mesh.
add_test(NAME wing_make_small COMMAND ${_wfgen} ${_wf} small --size small --load-steps 1)
set_tests_properties(wing_make_small PROPERTIES FIXTURES_SETUP wing_small_scene)
foreach(ranks 1 2)
  boltnet_run(wing_small ${ranks} ${_wf}/small.yaml ${_exact})
  set_tests_properties(run_wing_small_np${ranks} PROPERTIES FIXTURES_REQUIRED wing_small_scene)
  add_test(NAME wing_small_equilibrium_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_equilibrium.py ${BOLTNET_OUT}/wing_small_np${ranks} ${_wf}/small.yaml 1e-6)
  set_tests_properties(wing_small_equilibrium_np${ranks} PROPERTIES FIXTURES_REQUIRED "wing_small_scene;wing_small_np${ranks}")
endforeach()
boltnet_compare_ranks(wing_small 1e-8 2)
boltnet_run(wing_small_default 2 ${_wf}/small.yaml -output_fields false)
set_tests_properties(run_wing_small_default_np2 PROPERTIES FIXTURES_REQUIRED wing_small_scene)
add_test(NAME wing_small_default_vs_global
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/wing_small_np1/joints.csv ${BOLTNET_OUT}/wing_small_default_np2/joints.csv 1e-8)
set_tests_properties(wing_small_default_vs_global PROPERTIES FIXTURES_REQUIRED "wing_small_np1;wing_small_default_np2")
boltnet_run(wing_small_linear 1 ${_wf}/small.yaml -options_file ${_wf}/small.linear.opts -output_fields false)
boltnet_run(wing_small_linear_global 2 ${_wf}/small.yaml -options_file ${_wf}/small.linear.opts ${_exact} -output_fields false)
set_tests_properties(run_wing_small_linear_np1 run_wing_small_linear_global_np2 PROPERTIES FIXTURES_REQUIRED wing_small_scene)
add_test(NAME wing_small_linear_vs_global
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/wing_small_linear_np1/joints.csv ${BOLTNET_OUT}/wing_small_linear_global_np2/joints.csv 1e-8)
set_tests_properties(wing_small_linear_vs_global PROPERTIES FIXTURES_REQUIRED "wing_small_linear_np1;wing_small_linear_global_np2")

# Each part is meshed and checked in a process of its own, --jobs at a time (default: the cores it may use):
# one at a time writes the same meshes and tables, byte for byte.
add_test(NAME wing_make_tiny_one_job COMMAND ${_wfgen} ${_wf}/one-job tiny --size tiny --load-steps 2 --jobs 1)
set_tests_properties(wing_make_tiny_one_job PROPERTIES FIXTURES_SETUP wing_tiny_one_job)
add_test(NAME wing_make_tiny_jobs_same_files
  COMMAND sh -c "cd \"$0\" && for f in tiny.joints.csv tiny.bcs.csv tiny.patches.csv tiny.fasteners.csv tiny-mesh/*.msh; do cmp \"$f\" \"$1/$f\" || exit 1; done && echo 'the same files'"
          ${_wf} ${_wf}/one-job)
set_tests_properties(wing_make_tiny_jobs_same_files PROPERTIES FIXTURES_REQUIRED "wing_tiny_scene;wing_tiny_one_job")
boltnet_expect(wing_make_bad_jobs 1 --fail --match "--jobs must be at least 1"
  -- ${_wfgen} ${_wf}/bad bad --size tiny --jobs 0)

# Bad parameters stop the generator with a message naming them, and nothing is run.
boltnet_expect(wing_make_bad_gap 1 --fail --match "--butt-gap 5.* is too small for the tee's stem"
  -- ${_wfgen} ${_wf}/bad bad --size tiny --butt-gap 5)
boltnet_expect(wing_make_bad_nx 1 --fail --match "--nx 25 must be a multiple"
  -- ${_wfgen} ${_wf}/bad bad --size tiny --nx 25)
# A footprint radius larger than the elements would let boltnet attach fasteners to several nodes
# (and to nodes of a part's far side): the generator refuses, naming the fastener and the node, and
# leaves neither a scene nor meshes.
add_test(NAME wing_make_bad_clean COMMAND ${CMAKE_COMMAND} -E rm -rf ${_wf}/bad)
set_tests_properties(wing_make_bad_clean PROPERTIES FIXTURES_SETUP wing_bad_clean)
boltnet_expect(wing_make_bad_radius 1 --fail --match "fastener [0-9]+ .* node\\(s\\) of part '.*' lie within the footprint radius 30"
  -- ${_wfgen} ${_wf}/bad bad --size tiny --coupling-radius 30)
set_tests_properties(wing_make_bad_radius_np1 PROPERTIES FIXTURES_REQUIRED wing_bad_clean FIXTURES_SETUP wing_bad_radius)
add_test(NAME wing_make_bad_radius_writes_nothing
  COMMAND sh -c "test -d \"$0\" && test ! -e \"$0/bad.yaml\" && test ! -e \"$0/bad-mesh\" && test ! -e \"$0/.bad-mesh.tmp\"" ${_wf}/bad)
set_tests_properties(wing_make_bad_radius_writes_nothing PROPERTIES FIXTURES_REQUIRED wing_bad_radius)

# Each shell part is read and laid out by one rank (lib/patch/layout.cpp): on 2 and 3 ranks every
# part of the tiny junction is read once, no rank reads them all, and the nodes read add up to the
# parts' nodes counted in the Gmsh files themselves (check_read_per_rank.py).
foreach(ranks 2 3)
  add_test(NAME wing_tiny_read_per_rank_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_read_per_rank.py ${_wf}/tiny.yaml ${ranks} ${BOLTNET_OUT}/wing_tiny_read_np${ranks}.info
            -- ${BOLTNET_MPIRUN} ${ranks} --oversubscribe $<TARGET_FILE:boltnet_driver> -scene ${_wf}/tiny.yaml
               -output_dir ${BOLTNET_OUT}/wing_tiny_read_np${ranks} -load_table 1 -load_steps 1 -output_fields false
               -info ${BOLTNET_OUT}/wing_tiny_read_np${ranks}.info)
  set_tests_properties(wing_tiny_read_per_rank_np${ranks} PROPERTIES FIXTURES_REQUIRED wing_tiny_scene PROCESSORS ${ranks} ENVIRONMENT "${BOLTNET_ENV}")
endforeach()

# Cabin pressure (--cabin-pressure, docs/wing-fuselage.md): the pressure on the fuselage skin is its
# own load, and the scene runs five load cases on one set-up: the wing's path (flight), the pressure
# alone (cabin), both at 1 g (cruise), and the pressure brought on (pressurise) then held while the
# wing goes through its path (pressurised-flight). On 2 ranks: each outer box, which the pressure
# does not load, is held by the side-of-body fasteners alone: they balance its tip load in flight,
# cruise and pressurised-flight, and balance each other in cabin and pressurise; flight is the scene
# without pressure (1 rank's tiny run, 1e-8). With every fastener a linear spring, the held pressure
# against superposition: pressurised-flight at each step is flight plus pressurise's end (1e-8),
# condensed, on 1 rank.
add_test(NAME wing_make_tiny_cabin COMMAND ${_wfgen} ${_wf} tinyp --size tiny --load-steps 2 --cabin-pressure 0.0576)
set_tests_properties(wing_make_tiny_cabin PROPERTIES FIXTURES_SETUP wing_tiny_cabin_scene)
boltnet_run(wing_tiny_cabin 2 ${_wf}/tinyp.yaml ${_exact})
set_tests_properties(run_wing_tiny_cabin_np2 PROPERTIES FIXTURES_REQUIRED wing_tiny_cabin_scene)
foreach(case flight cruise cabin pressurise pressurised-flight)
  set(_tip "")
  if(case STREQUAL cabin OR case STREQUAL pressurise)
    set(_tip --no-tip-load)
  endif()
  add_test(NAME wing_tiny_cabin_${case}_equilibrium
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_junction_equilibrium.py ${BOLTNET_OUT}/wing_tiny_cabin_np2/${case} ${_wf}/tinyp.yaml 1e-6 ${_tip})
  set_tests_properties(wing_tiny_cabin_${case}_equilibrium PROPERTIES FIXTURES_REQUIRED "wing_tiny_cabin_scene;wing_tiny_cabin_np2")
endforeach()
add_test(NAME wing_tiny_cabin_flight_as_without
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/compare_csv.py ${BOLTNET_OUT}/wing_tiny_np1/joints.csv ${BOLTNET_OUT}/wing_tiny_cabin_np2/flight/joints.csv 1e-8)
set_tests_properties(wing_tiny_cabin_flight_as_without PROPERTIES FIXTURES_REQUIRED "wing_tiny_np1;wing_tiny_cabin_np2")
boltnet_run(wing_tiny_cabin_linear 1 ${_wf}/tinyp.yaml -options_file ${_wf}/tinyp.linear.opts -load_cases flight,pressurise,pressurised-flight -output_fields false)
set_tests_properties(run_wing_tiny_cabin_linear_np1 PROPERTIES FIXTURES_REQUIRED wing_tiny_cabin_scene)
add_test(NAME wing_tiny_cabin_held_superposition
  COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_superposition.py ${BOLTNET_OUT}/wing_tiny_cabin_linear_np1/pressurised-flight/joints.csv
          ${BOLTNET_OUT}/wing_tiny_cabin_linear_np1/flight/joints.csv ${BOLTNET_OUT}/wing_tiny_cabin_linear_np1/pressurise/joints.csv 1e-8)
set_tests_properties(wing_tiny_cabin_held_superposition PROPERTIES FIXTURES_REQUIRED wing_tiny_cabin_linear_np1)

# The tip load through a rigid patch (--tip-load rigid): a 6-dof node at the tip section's centre
# tied to each part's whole tip section (fastener table column `footprint`), loaded with the beam
# loads' resultant. With the rigid patch in the free body, each outer box is again held by the
# side-of-body fasteners alone, which balance the tip load at every step, on 1, 2 and 3 ranks.
wing_tiny_balanced(tinyr --tip-load rigid)
# The ties carry the whole tip load; the most loaded joint the run reports is a fastener's
# (check_most_loaded.py recomputes it from joints.csv without the ties), on 1, 2 and 3 ranks.
foreach(ranks 1 2 3)
  add_test(NAME wing_tinyr_most_loaded_np${ranks}
    COMMAND ${BOLTNET_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/check_most_loaded.py ${BOLTNET_OUT}/wing_tinyr_np${ranks} ${_wf}/tinyr.joints.csv)
  set_tests_properties(wing_tinyr_most_loaded_np${ranks} PROPERTIES FIXTURES_REQUIRED "wing_tinyr_scene;wing_tinyr_np${ranks}")
endforeach()
