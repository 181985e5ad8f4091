# Joint parameter identification sources: target_sources(boltnet PRIVATE ...).
# Macroelement parameters from a fastener's geometry (flexibility formulas) and from a test curve
# (least-squares fit of the frictional law); docs/identify.md.
target_sources(boltnet PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/fastener.cpp
  ${CMAKE_CURRENT_LIST_DIR}/curve.cpp
  ${CMAKE_CURRENT_LIST_DIR}/options.cpp
  ${CMAKE_CURRENT_LIST_DIR}/coupon.cpp)

# The driver boltnet-identify (drivers/identify.cpp): geometry mode and curve mode.
add_executable(boltnet_identify ${PROJECT_SOURCE_DIR}/drivers/identify.cpp)
set_target_properties(boltnet_identify PROPERTIES OUTPUT_NAME boltnet-identify)
target_link_libraries(boltnet_identify PRIVATE boltnet)
target_include_directories(boltnet_identify PRIVATE ${PROJECT_SOURCE_DIR}/lib)
install(TARGETS boltnet_identify RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
