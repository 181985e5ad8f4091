# What `cmake --install build --prefix P` puts besides the library, headers, drivers and plugin
# (lib/, drivers/, plugins/): what a user of the installed package needs to reproduce README.md,
# under the GNU directories (docs/install.md has the layout; test/check_install.sh runs the README's
# commands against it).
#   P/share/boltnet/scenes     the scenes (YAML, CSV tables, meshes); the driver finds them by name
#   P/share/boltnet/solvers    options files for other linear solvers (-options_file)
#   P/share/boltnet/scripts    the scripts a user runs: charts, the plate-grid generator, mpienv
#   P/share/boltnet/identify   load-slip curves for boltnet-identify -curve
#   P/share/doc/boltnet        README.md and docs/ (the same relative links as in the repository)
set(BOLTNET_INSTALL_DATADIR "${CMAKE_INSTALL_DATADIR}/boltnet")

install(DIRECTORY ${PROJECT_SOURCE_DIR}/share/scenes/ DESTINATION ${BOLTNET_INSTALL_DATADIR}/scenes)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/share/solvers/ DESTINATION ${BOLTNET_INSTALL_DATADIR}/solvers)
install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/plot_joints.py ${PROJECT_SOURCE_DIR}/scripts/plot_fields.py
                 ${PROJECT_SOURCE_DIR}/scripts/make-plate-grid
        DESTINATION ${BOLTNET_INSTALL_DATADIR}/scripts)
# Sourced, not run (". scripts/mpienv"): Open MPI as root and more ranks than cores.
install(FILES ${PROJECT_SOURCE_DIR}/scripts/mpienv DESTINATION ${BOLTNET_INSTALL_DATADIR}/scripts)
# The example curves of docs/identify.md (the other files of test/data/identify are bad input for tests).
install(FILES ${PROJECT_SOURCE_DIR}/test/data/identify/cyclic.csv ${PROJECT_SOURCE_DIR}/test/data/identify/stick-only.csv
        DESTINATION ${BOLTNET_INSTALL_DATADIR}/identify)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
