# Frictional networks beyond one dimension against an independent reference (docs/verification-2d.md).
# test/ref2d/ holds a solver for networks of rigid patches written from docs/joint-laws.md and
# docs/scenes.md alone (network.py), a generator of random networks (make_scene.py), the comparison
# (check_network.py) and the eccentric bolt group's closed forms (bolt_group.py). Included by
# test/CMakeLists.txt, which defines boltnet_run and the BOLTNET_* variables.
set(_ref2d ${CMAKE_CURRENT_SOURCE_DIR}/ref2d)
set(_ref2d_out ${BOLTNET_OUT}/ref2d)
set(_ref2d_check ${BOLTNET_PYTHON} ${_ref2d}/check_network.py)

# The reference itself (requirement: a reference that can be trusted): its tangents against central
# differences of its forces (Newton's convergence), and the bolt group's closed forms against their
# limits (e -> 0: n G; e -> infinity: rotation about the centroid) and against the reference network
# with lever arms (rigid plate: elastic centroid method to 3e-14, IC method to 1e-10).
add_test(NAME ref2d_reference_tangent COMMAND ${BOLTNET_PYTHON} ${_ref2d}/network.py --selftest)
add_test(NAME ref2d_bolt_group_closed_forms COMMAND ${BOLTNET_PYTHON} ${_ref2d}/bolt_group.py selftest)

# Random networks (docs/joint-laws.md, frictional law in the joint plane; docs/solver.md, load steps;
# standards: independent of the rank count). Each scene is written at test time from its seed; boltnet
# runs it on 1, 2 and 3 ranks and every row of joints.csv (jumps, forces, slips, states) is compared
# with the reference at 1e-8 of each quantity's scale: the bound of boltnet's round-off stop with
# kr = 1e9 (check_network.py explains it; measured at most 5.6e-9 over 24 scenes). --min-turn 30: the scene must turn
# some joint's slip by 30 degrees or more between sliding steps (the 2D law is exercised).
#   net12, net2: 3D (tilted bolt axes, clamp coupling, offsets), 10 slip turns over 10 degrees each;
#   net8-planar: every axis z, boltnet's out-of-plane jump and force must stay zero (59 turns);
#   net4: 3D with a cut-back in the path (the reference takes boltnet's steps), few turns.
# ref2d_network(NAME SEED [GENERATE args...] [CHECK args...]): scene net<NAME> from make_scene.py
# SEED GENERATE..., run on 1, 2 and 3 ranks, each compared by check_network.py CHECK...
function(ref2d_network name seed)
  cmake_parse_arguments(PARSE_ARGV 2 R "" "" "GENERATE;CHECK")
  set(scene ${_ref2d_out}/net${name}.yaml)
  add_test(NAME ref2d_make_net${name} COMMAND ${BOLTNET_PYTHON} ${_ref2d}/make_scene.py ${seed} ${_ref2d_out} ${R_GENERATE})
  set_tests_properties(ref2d_make_net${name} PROPERTIES FIXTURES_SETUP ref2d_scene_net${name})
  foreach(ranks 1 2 3)
    boltnet_run(ref2d_net${name} ${ranks} ${scene})
    set_tests_properties(run_ref2d_net${name}_np${ranks} PROPERTIES FIXTURES_REQUIRED ref2d_scene_net${name})
    add_test(NAME ref2d_net${name}_vs_reference_np${ranks}
      COMMAND ${_ref2d_check} ${BOLTNET_OUT}/ref2d_net${name}_np${ranks}/joints.csv ${scene} ${R_CHECK})
    set_tests_properties(ref2d_net${name}_vs_reference_np${ranks} PROPERTIES FIXTURES_REQUIRED "ref2d_net${name}_np${ranks};ref2d_scene_net${name}")
  endforeach()
endfunction()
ref2d_network(12 12 CHECK --min-turn 30)
ref2d_network(2 2 CHECK --min-turn 30)
ref2d_network(8-planar 8 GENERATE --planar CHECK --planar --min-turn 30)
ref2d_network(4 4)

# The same network solved to round-off: kr = 1e5 (rotations are decoupled from the compared
# quantities on rigid patches, and boltnet's round-off stop scales with the largest row of J, kr's)
# and -snes_rtol 1e-14. The model then agrees to 1e-10 (measured 3.5e-13), on 1 and 3 ranks.
add_test(NAME ref2d_make_net12_kr COMMAND ${BOLTNET_PYTHON} ${_ref2d}/make_scene.py 12 ${_ref2d_out} --kr 1e5)
set_tests_properties(ref2d_make_net12_kr PROPERTIES FIXTURES_SETUP ref2d_scene_net12_kr)
foreach(ranks 1 3)
  boltnet_run(ref2d_net12_kr ${ranks} ${_ref2d_out}/net12-kr100000.yaml -snes_rtol 1e-14)
  set_tests_properties(run_ref2d_net12_kr_np${ranks} PROPERTIES FIXTURES_REQUIRED ref2d_scene_net12_kr)
  add_test(NAME ref2d_net12_kr_vs_reference_np${ranks}
    COMMAND ${_ref2d_check} ${BOLTNET_OUT}/ref2d_net12_kr_np${ranks}/joints.csv ${_ref2d_out}/net12-kr100000.yaml --rtol 1e-10 --min-turn 30)
  set_tests_properties(ref2d_net12_kr_vs_reference_np${ranks} PROPERTIES FIXTURES_REQUIRED "ref2d_net12_kr_np${ranks};ref2d_scene_net12_kr")
endforeach()

# The comparison can fail: the reference given one joint type's kg 1% higher than boltnet's differs by
# 3.9e-5 of the force scale, and the check says so.
boltnet_expect(ref2d_detects_a_changed_kg 1 --fail --match "FAIL: step .* joint" --match "failures \\(tolerance 1e-08"
  -- ${_ref2d_check} ${BOLTNET_OUT}/ref2d_net12_np1/joints.csv ${_ref2d_out}/net12.yaml -joint_f0_kg 879.45)
set_tests_properties(ref2d_detects_a_changed_kg_np1 PROPERTIES FIXTURES_REQUIRED "ref2d_net12_np1;ref2d_scene_net12")

# A state on a threshold is explained, never skipped: fig3c's load stops exactly at G and at -G
# (robustness_tests.cmake), where |F_tr| = G and the reference finds the joint on the slip
# threshold. Both say stick; with step 1's word doctored to slide the check passes and prints why,
# with step 3's (load 0, F_tr = 0, far from any threshold) it fails.
set(_thr ${BOLTNET_OUT}/hard_threshold_1_np1/joints.csv)
set(_thr_opts ${BOLTNET_SCENES}/fig3c.yaml -load_table 3000,-3000,0 -load_steps 1)
boltnet_expect(ref2d_threshold_same_state 1 --match "rows on a threshold: 2, of which 0"
  -- ${_ref2d_check} ${_thr} ${_thr_opts})
boltnet_expect(ref2d_threshold_explained 1 --match "threshold: step 1 joint 0: boltnet slide .*reference stick .*the joint sits on a threshold, \\|F_tr\\| - G = 0"
  -- sh -c "sed 's/^1,\\([^,]*\\),0,stick,/1,\\1,0,slide,/' \"$0\" > \"$1\" && \"$2\" \"$3\" \"$1\" \"$4\" -load_table 3000,-3000,0 -load_steps 1"
  ${_thr} ${BOLTNET_OUT}/hard_threshold_1_np1/doctored-step1.csv ${BOLTNET_PYTHON} ${_ref2d}/check_network.py ${BOLTNET_SCENES}/fig3c.yaml)
boltnet_expect(ref2d_state_off_threshold_fails 1 --fail --match "FAIL: step 3 joint 0: boltnet slide .*away from any threshold"
  -- sh -c "sed 's/^3,\\([^,]*\\),0,stick,/3,\\1,0,slide,/' \"$0\" > \"$1\" && \"$2\" \"$3\" \"$1\" \"$4\" -load_table 3000,-3000,0 -load_steps 1"
  ${_thr} ${BOLTNET_OUT}/hard_threshold_1_np1/doctored-step3.csv ${BOLTNET_PYTHON} ${_ref2d}/check_network.py ${BOLTNET_SCENES}/fig3c.yaml)
set_tests_properties(ref2d_threshold_same_state_np1 ref2d_threshold_explained_np1 ref2d_state_off_threshold_fails_np1
  PROPERTIES FIXTURES_REQUIRED hard_threshold_1_np1)

# The shipped test scene chain (9 joints of the three laws, 2D loading and reversal) against the
# reference, from the runs test/CMakeLists.txt already makes on 1, 2 and 3 ranks.
foreach(ranks 1 2 3)
  add_test(NAME ref2d_chain_vs_reference_np${ranks}
    COMMAND ${_ref2d_check} ${BOLTNET_OUT}/chain_np${ranks}/joints.csv ${BOLTNET_TEST_SCENES}/chain.yaml)
  set_tests_properties(ref2d_chain_vs_reference_np${ranks} PROPERTIES FIXTURES_REQUIRED chain_np${ranks})
endforeach()

# ---------------------------------------------------------------------------------------------------
# The eccentric bolt group (bolt_group.py): six fasteners, load at e = 300 mm.
# Rigid patches attach every joint at their single node (docs/scenes.md), so a rigid plate has no
# lever arms; the plate here is a shell patch, whose joints attach at their positions.
set(_group ${BOLTNET_PYTHON} ${_ref2d}/bolt_group.py)
add_test(NAME ref2d_group_scenes COMMAND sh -c "\"$0\" \"$1\" scene \"$2/E1\" --plate shell --control force --E 7.2e7 && \"$0\" \"$1\" scene \"$2/E2\" --plate shell --control force --E 7.2e8 && \"$0\" \"$1\" scene \"$2\" --plate shell --control displacement && \"$0\" \"$1\" scene \"$2\" --plate rigid --control force && \"$0\" \"$1\" scene \"$2\" --plate rigid --control displacement"
  ${BOLTNET_PYTHON} ${_ref2d}/bolt_group.py ${_ref2d_out})
set_tests_properties(ref2d_group_scenes PROPERTIES FIXTURES_SETUP ref2d_group_scenes)

# (a) Elastic, identical springs, on shell plates of E = 7.2e7 and 7.2e8 MPa: the plate's compliance
# is an error in 1/E (measured 2.28e-4, 2.29e-5: ratio 9.99); the Richardson extrapolation to a rigid
# plate gives the elastic centroid method to 2.7e-8 (tolerance 1e-7: the O(1/E^2) remainder is 5e-9,
# from the pair 7.2e6/7.2e7, and the stiffer plate's solve loses ~1e-8 to its conditioning).
foreach(E E1 E2)
  boltnet_run(ref2d_group_${E} 1 ${_ref2d_out}/${E}/group-shell-force.yaml)
  set_tests_properties(run_ref2d_group_${E}_np1 PROPERTIES FIXTURES_REQUIRED ref2d_group_scenes)
endforeach()
add_test(NAME ref2d_group_elastic_centroid
  COMMAND ${_group} elastic-limit ${BOLTNET_OUT}/ref2d_group_E1_np1/joints.csv ${BOLTNET_OUT}/ref2d_group_E2_np1/joints.csv --ratio 10 --rtol 1e-7)
set_tests_properties(ref2d_group_elastic_centroid PROPERTIES FIXTURES_REQUIRED "ref2d_group_E1_np1;ref2d_group_E2_np1")

# (b) Ultimate, pure Coulomb, the load point pushed 15 mm: every fastener slides and carries G
# perpendicular to its ray from the instantaneous centre; the plateau does not depend on the plate's
# elasticity (at a constant load the plate's strain is constant, the slip increments are a rigid
# rotation), so an aluminium plate gives the IC method exactly once the transition has died out (by
# 8 mm). Solved to round-off (-snes_rtol 1e-14) on 1 rank: P_u to 2.6e-10, forces to 1.2e-9 of G
# (tolerance 1e-8). With the default -snes_rtol 1e-10 on 2 ranks: the step's initial residual is the
# 1.25 mm increment imposed on the 1e7 N/mm loader, 1.25e7 N, so a step may stop at 1.25e-3 N, 4e-7
# of G (tolerance 1e-6; measured 7.7e-8).
boltnet_run(ref2d_group_plateau_tight 1 ${_ref2d_out}/group-shell-displacement.yaml -snes_rtol 1e-14)
boltnet_run(ref2d_group_plateau 2 ${_ref2d_out}/group-shell-displacement.yaml)
foreach(run ref2d_group_plateau_tight_np1 ref2d_group_plateau_np2)
  set_tests_properties(run_${run} PROPERTIES FIXTURES_REQUIRED ref2d_group_scenes)
endforeach()
add_test(NAME ref2d_group_ic_method_tight COMMAND ${_group} plateau ${BOLTNET_OUT}/ref2d_group_plateau_tight_np1/joints.csv --rtol 1e-8)
set_tests_properties(ref2d_group_ic_method_tight PROPERTIES FIXTURES_REQUIRED ref2d_group_plateau_tight_np1)
add_test(NAME ref2d_group_ic_method_np2 COMMAND ${_group} plateau ${BOLTNET_OUT}/ref2d_group_plateau_np2/joints.csv --rtol 1e-6)
set_tests_properties(ref2d_group_ic_method_np2 PROPERTIES FIXTURES_REQUIRED ref2d_group_plateau_np2)

# The same group on a RIGID plate, against the exact closed forms: a joint with a position acts on a
# rigid patch at that position, as a rigid-body slave of the patch's node (u + theta x (x - X), and
# its force puts the moment (x - X) x f on the node: docs/joint-laws.md, "Where a joint acts"). The
# reference network with --attach position gives these closed forms to 3e-14 and 1e-10
# (ref2d_bolt_group_closed_forms). kr = 1e-3 N mm/rad: (a) includes it exactly, in (b) it costs 6e-10.
# (b) is solved to round-off (-snes_rtol 1e-14) for the reason given for the shell plate above.
set(_rigid ${_ref2d_out}/group-rigid)
add_test(NAME ref2d_group_rigid_elastic_centroid
  COMMAND sh -c "\"$0\" -scene \"$1-force.yaml\" -output_dir \"$1-force\" && \"$2\" \"$3\" elastic \"$1-force/joints.csv\" --kr 1e-3 --rtol 1e-8"
          $<TARGET_FILE:boltnet_driver> ${_rigid} ${BOLTNET_PYTHON} ${_ref2d}/bolt_group.py)
add_test(NAME ref2d_group_rigid_ic_method
  COMMAND sh -c "\"$0\" -scene \"$1-displacement.yaml\" -output_dir \"$1-displacement\" -snes_rtol 1e-14 && \"$2\" \"$3\" plateau \"$1-displacement/joints.csv\" --rtol 1e-8"
          $<TARGET_FILE:boltnet_driver> ${_rigid} ${BOLTNET_PYTHON} ${_ref2d}/bolt_group.py)
set_tests_properties(ref2d_group_rigid_elastic_centroid ref2d_group_rigid_ic_method PROPERTIES
  FIXTURES_REQUIRED ref2d_group_scenes ENVIRONMENT "${BOLTNET_ENV}")
