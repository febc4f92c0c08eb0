# beamsolid_add_plugin(name source...): a plugin module for ops.loadPlugin().
# It compiles the sources as C++20 against BeamSolid::beamsolid, adds the ABI
# stamp of these headers (core/PluginAbi.h) that loadPlugin checks, hides
# every symbol but the two BeamSolid looks up (beamsolid_register and the
# stamp; so two plugins' helpers never collide), and sets the RPATH to the
# folder of the libbeamsolid.so it was built against.
function(beamsolid_add_plugin name)
  if(NOT ARGN)
    message(FATAL_ERROR "beamsolid_add_plugin(${name}): give the plugin's source files")
  endif()
  # The stamp source lies beside this file, wherever the function is called from.
  add_library(${name} MODULE ${ARGN} "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/beamsolid_plugin_stamp.cpp")
  target_link_libraries(${name} PRIVATE BeamSolid::beamsolid)
  target_compile_features(${name} PRIVATE cxx_std_20)
  set_target_properties(${name} PROPERTIES
    CXX_EXTENSIONS OFF
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON
    BUILD_RPATH "$<TARGET_FILE_DIR:BeamSolid::beamsolid>"
    INSTALL_RPATH "$<TARGET_FILE_DIR:BeamSolid::beamsolid>")
endfunction()
