# `cmake --install build [--prefix P]`: the CLI, libscbt.so, the public headers, the CMake package
# (scbt::scbt), scbt.pc and the Python module (docs/install.md). Everything lands in component
# `scbt` (the Debian package scbt); the ROS node installs itself into component `ros` (ros/).
include(CMakePackageConfigHelpers)

# The user-facing API: tracker, options, per-frame result, loss/confidence, box init, polygon I/O,
# the paper's stage functions and the depth lift -- plus the headers these include (the Tracker
# class holds its stages by value). CI compiles them against the installed tree alone, so a
# public header including a private one fails there (scripts/ci_install.sh).
set(SCBT_PUBLIC_HEADERS
    geometry/polygon.h geometry/polygon_io.h geometry/boundary_query.h geometry/shape_descriptor.h
    lines/line_detector.h lines/adaptive_thresholds.h lines/exposure.h lines/edge_blur.h
    filter/segment_filter.h
    graph/segment_graph.h
    cycles/bdsp.h cycles/segment_units.h
    choice/boundary_choice.h choice/boundary_distance_cache.h
    tracker/tracker.h tracker/tracker_options.h tracker/option_table.h tracker/track_state.h tracker/confidence.h
    tracker/box_init.h tracker/cycle_stage.h tracker/motion_model.h tracker/reacquire.h
    tracker/contrast_profile.h tracker/frame_checks.h tracker/scene_keyframes.h
    tracker/motion_estimate.h tracker/phase_correlation.h tracker/shape_memory.h
    tracker/reacquire_view_change.h tracker/reacquire_appearance.h
    depth/boundary_3d.h depth/boundary_3d_io.h depth/camera_info.h depth/circle_fit.h
    depth/depth_options.h depth/pinhole_camera.h)
foreach(header ${SCBT_PUBLIC_HEADERS})
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/src/scbt/${header}
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/scbt/${folder} COMPONENT scbt)
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/include/scbt/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/scbt COMPONENT scbt)

install(TARGETS scbt RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT scbt)
install(TARGETS scbt_shared EXPORT scbtTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT scbt NAMELINK_COMPONENT scbt)

set(SCBT_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/scbt)
install(EXPORT scbtTargets NAMESPACE scbt:: DESTINATION ${SCBT_CMAKE_DIR} COMPONENT scbt)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/scbtConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/scbtConfig.cmake INSTALL_DESTINATION ${SCBT_CMAKE_DIR})
# 0.x: a minor release may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/scbtConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/scbtConfig.cmake ${PROJECT_BINARY_DIR}/scbtConfigVersion.cmake
        DESTINATION ${SCBT_CMAKE_DIR} COMPONENT scbt)

# scbt.pc, in two forms: with the libdir as the linked program's run-time search path
# (-Wl,-rpath), so that a pkg-config consumer runs from any prefix without LD_LIBRARY_PATH; and
# without it, for a prefix the loader searches anyway (/usr, and the Debian package, which
# installs with SCBT_SYSTEM_PREFIX set: scbt_package.cmake). Chosen when installing.
file(RELATIVE_PATH SCBT_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
set(SCBT_PC_RUNPATH " -Wl,-rpath,\${libdir}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/scbt.pc.in ${PROJECT_BINARY_DIR}/scbt.pc @ONLY)
set(SCBT_PC_RUNPATH "")
configure_file(${PROJECT_SOURCE_DIR}/cmake/scbt.pc.in ${PROJECT_BINARY_DIR}/system/scbt.pc @ONLY)
install(
  CODE "
    if(SCBT_SYSTEM_PREFIX OR CMAKE_INSTALL_PREFIX STREQUAL \"/usr\")
      set(scbt_pc \"${PROJECT_BINARY_DIR}/system/scbt.pc\")
    else()
      set(scbt_pc \"${PROJECT_BINARY_DIR}/scbt.pc\")
    endif()
    file(INSTALL \"\${scbt_pc}\" DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig\")"
  COMPONENT scbt)

# Where Debian's /usr/bin/python3 looks (P/lib/python3/dist-packages), with its type stub.
if(TARGET scbt_python)
  set(SCBT_PYTHON_DIR lib/python3/dist-packages)
  install(TARGETS scbt_python LIBRARY DESTINATION ${SCBT_PYTHON_DIR} COMPONENT scbt)
  install(FILES ${PROJECT_SOURCE_DIR}/python/scbt.pyi DESTINATION ${SCBT_PYTHON_DIR} COMPONENT scbt)
endif()
