# libscbt.so: the user-facing library, one shared object built from the objects of the core
# stage libraries (geometry, depth, lines, filter, graph, cycles, choice, tracker). Shared, so
# that CGAL, GMP, MPFR and OpenCV's imgproc/ximgproc stay private link dependencies
# (dpkg-shlibdeps finds them); consumers see OpenCV core and Eigen only, through the headers.
# The CLI, the Python module and the tests keep linking the static stage libraries.
include(GNUInstallDirs)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)  # used by the depth headers

set(SCBT_CORE_LIBRARIES scbt_read scbt_geometry scbt_depth scbt_lines scbt_filter scbt_graph scbt_cycles
                        scbt_choice scbt_motion scbt_tracker)

# The version, from project(VERSION) only: scbt/version.h for the CLI, the Python module and users.
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.h.in
               ${PROJECT_BINARY_DIR}/include/scbt/version.h @ONLY)
add_library(scbt_version INTERFACE)
target_include_directories(scbt_version INTERFACE $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>)

set(scbt_objects "")
foreach(library ${SCBT_CORE_LIBRARIES})
  list(APPEND scbt_objects $<TARGET_OBJECTS:${library}>)
endforeach()
add_library(scbt_shared SHARED ${scbt_objects})
add_library(scbt::scbt ALIAS scbt_shared)
set_target_properties(scbt_shared PROPERTIES OUTPUT_NAME scbt EXPORT_NAME scbt
                      VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
# The static libraries after their own objects bring in only their dependencies (OpenCV, CGAL's
# GMP/MPFR): every symbol of theirs is already defined by the objects.
target_link_libraries(scbt_shared PRIVATE ${SCBT_CORE_LIBRARIES} PUBLIC opencv_core Eigen3::Eigen)
target_include_directories(
  scbt_shared PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>
                     $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>
                     $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
