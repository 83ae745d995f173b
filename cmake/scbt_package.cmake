# `cpack -G DEB` in the build folder: scbt_<version>_amd64.deb (CLI, libscbt.so, headers, CMake
# package, scbt.pc, Python module) and, when the ROS node is built, scbt-ros_<version>_amd64.deb
# (a separate package, so that users without ROS do not pull ROS in). Depends come from
# dpkg-shlibdeps over the installed binaries, plus the Python interpreter the module was built for.
set(CPACK_PACKAGE_NAME scbt)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR scbt)
set(CPACK_PACKAGE_CONTACT "scbt maintainers <scbt@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "real-time salient closed boundary tracking via line segment perceptual grouping")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# A shlibs file for libscbt.so, so that packages built against it get their Depends.
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS_POLICY ">=")

set(CPACK_DEBIAN_SCBT_PACKAGE_NAME scbt)
set(CPACK_COMPONENT_SCBT_DESCRIPTION
    "scbt CLI, libscbt.so with headers, CMake package and pkg-config file, Python 3 module")
if(TARGET scbt_python)
  math(EXPR next_minor "${Python3_VERSION_MINOR} + 1")
  # The module is built for this interpreter's ABI (e.g. 3.11) and hands frames over as numpy arrays.
  set(CPACK_DEBIAN_SCBT_PACKAGE_DEPENDS
      "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}~), python3 (<< ${Python3_VERSION_MAJOR}.${next_minor}), python3-numpy")
endif()
set(CPACK_DEBIAN_ROS_PACKAGE_NAME scbt-ros)
set(CPACK_COMPONENT_ROS_DESCRIPTION "scbt_node: the scbt tracker as a ROS 1 node (package scbt_ros)")
set(CPACK_DEBIAN_ROS_PACKAGE_DEPENDS "scbt (= ${PROJECT_VERSION})")
# scbt_node needs libscbt.so from the scbt package (the Depends above): dpkg-shlibdeps finds it
# where CPack staged that package, under the packaging folder -- the build folder, or the one
# `cpack -B DIR` names, known only when cpack runs: so set there (CPACK_PROJECT_CONFIG_FILE).
file(
  CONFIGURE
  OUTPUT ${PROJECT_BINARY_DIR}/scbt_cpack_options.cmake
  CONTENT
    [[set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS
    "${CPACK_PACKAGE_DIRECTORY}/_CPack_Packages/${CPACK_SYSTEM_NAME}/${CPACK_GENERATOR}/${CPACK_PACKAGE_FILE_NAME}/scbt${CPACK_PACKAGING_INSTALL_PREFIX}/@CMAKE_INSTALL_LIBDIR@")
]]
  @ONLY)
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_BINARY_DIR}/scbt_cpack_options.cmake)
set(CPACK_COMPONENT_ROS_DEPENDS scbt)
# Installed under /usr, where the loader looks: scbt.pc without a run-time search path
# (scbt_install.cmake).
set(CPACK_CUSTOM_INSTALL_VARIABLES SCBT_SYSTEM_PREFIX=ON)

get_cmake_property(SCBT_INSTALL_COMPONENTS COMPONENTS)
set(CPACK_COMPONENTS_ALL scbt)
if(ros IN_LIST SCBT_INSTALL_COMPONENTS)
  list(APPEND CPACK_COMPONENTS_ALL ros)
endif()
include(CPack)
