# Nastran bulk data reader (docs/nastran.md): target_sources(boltnet PRIVATE ...).
# The reader itself is pure C++ (no PETSc): the unit tests compile BOLTNET_NASTRAN_SOURCES directly
# (with lib/shell/material.cpp, which section.cpp uses). petsc.cpp is the PETSc-facing wrapper.
set(BOLTNET_NASTRAN_SOURCES
  ${CMAKE_CURRENT_LIST_DIR}/lexer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/fields.cpp
  ${CMAKE_CURRENT_LIST_DIR}/cards.cpp
  ${CMAKE_CURRENT_LIST_DIR}/connect.cpp
  ${CMAKE_CURRENT_LIST_DIR}/coords.cpp
  ${CMAKE_CURRENT_LIST_DIR}/resolve.cpp
  ${CMAKE_CURRENT_LIST_DIR}/reader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/expand.cpp
  ${CMAKE_CURRENT_LIST_DIR}/section.cpp
  ${CMAKE_CURRENT_LIST_DIR}/model.cpp
  ${CMAKE_CURRENT_LIST_DIR}/rbe3.cpp
  ${CMAKE_CURRENT_LIST_DIR}/report.cpp
  CACHE INTERNAL "Pure C++ sources of the Nastran reader")
target_sources(boltnet PRIVATE ${BOLTNET_NASTRAN_SOURCES} ${CMAKE_CURRENT_LIST_DIR}/petsc.cpp)

# nastran-summary (a tool, not installed): counts, unused cards, bounding box and subcase loads of a
# deck; scripts/verify-nastran-decks runs it over a folder of decks.
add_executable(nastran_summary ${CMAKE_CURRENT_LIST_DIR}/summary.cpp)
set_target_properties(nastran_summary PROPERTIES OUTPUT_NAME nastran-summary)
target_link_libraries(nastran_summary PRIVATE boltnet)
target_include_directories(nastran_summary PRIVATE ${PROJECT_SOURCE_DIR}/lib)
