# `cmake --install build [--prefix P]`: the CLI, libscbt.so, the public headers, the CMake package
# (scbt::scbt), scbt.pc and the Python module (docs/install.md). Everything lands in component
# `scbt` (the Debian package scbt); the ROS node installs itself into component `ros` (ros/).
include(CMakePackageConfigHelpers)

# What users call: the tracker (tracker.h, behind a pimpl), its options and per-frame result, polygon
# I/O and the depth lift (boundary_3d, its I/O and camera intrinsics) -- plus the headers these
# include: the option structs still live beside their stages (lines/, cycles/, tracker/). CI
# compiles each against the installed tree alone, so a public header including a private one
# fails there (scripts/ci_install.sh).
set(SCBT_PUBLIC_HEADERS
    tracker/tracker.h tracker/tracker_options.h tracker/option_table.h tracker/object_memory.h tracker/track_state.h tracker/confidence.h
    geometry/polygon.h geometry/polygon_io.h
    depth/boundary_3d.h depth/boundary_3d_io.h depth/camera_info.h
    # included by the ones above
    tracker/contrast_profile.h tracker/reacquire_view_change.h tracker/reacquire_appearance.h
    geometry/shape_descriptor.h graph/segment_graph.h cycles/bdsp.h cycles/segment_units.h
    lines/line_detector.h lines/adaptive_thresholds.h lines/exposure.h lines/edge_blur.h
    depth/circle_fit.h depth/depth_options.h depth/pinhole_camera.h)
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
