# What `cmake --install build --prefix P` puts where, and the Debian package `cpack -G DEB` makes of
# it. The installed programs find everything relative to their own path (worlds/base/src/layout.cpp), so a
# prefix can be moved: P/bin/frob run my.cpp works from any folder, with no source tree present.
#
#   P/bin/frob                                  the command
#   P/libexec/frob/frob-controller-host         the controller host, and the sandbox launcher it runs under
#   P/libexec/frob/frob-sandbox
#   P/include/frob/...                          the headers controllers and student projects use
#   P/lib/libfrob_frob.a, P/lib/cmake/frob/     frob::frob for find_package(frob CONFIG)
#   P/lib/frob/frob.pch, frob-headers.yaml      what `frob run` compiles a controller against
#   P/lib/frob/examples/NN_name.so              the numbered examples, prebuilt
#   P/share/frob/{worlds,examples,assignments,models,template}   data, sources and the student project template
#   P/share/frob/version                        the marker an installed frob recognises its prefix by
include(CMakePackageConfigHelpers)

set(frob_libdir "${CMAKE_INSTALL_LIBDIR}/frob")
set(frob_datadir "${CMAKE_INSTALL_DATADIR}/frob")
set(frob_libexecdir "${CMAKE_INSTALL_LIBEXECDIR}/frob")
set(frob_cmakedir "${CMAKE_INSTALL_LIBDIR}/cmake/frob")

install(TARGETS frob_app RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")
install(TARGETS frob_controller_host frob_sandbox_program RUNTIME DESTINATION "${frob_libexecdir}")

# frob::frob: the library controllers are written against, its headers, and the settings it carries.
# A student project needs C++20 (coroutines) to include them.
target_compile_features(frob_frob PUBLIC cxx_std_20)
set_target_properties(frob_frob PROPERTIES EXPORT_NAME frob)
set_target_properties(frob_build_options PROPERTIES EXPORT_NAME build_options)
install(TARGETS frob_frob frob_build_options EXPORT frobTargets ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/frob/include/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}")
install(EXPORT frobTargets NAMESPACE frob:: DESTINATION "${frob_cmakedir}")
configure_package_config_file("${PROJECT_SOURCE_DIR}/cmake/frobConfig.cmake.in" "${PROJECT_BINARY_DIR}/frobConfig.cmake"
  INSTALL_DESTINATION "${frob_cmakedir}")
write_basic_package_version_file("${PROJECT_BINARY_DIR}/frobConfigVersion.cmake" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/frobConfig.cmake" "${PROJECT_BINARY_DIR}/frobConfigVersion.cmake"
  DESTINATION "${frob_cmakedir}")

# What `frob run` compiles a controller against: the precompiled header and the overlay that shows
# it the installed headers (see course/run/CMakeLists.txt), and the examples prebuilt.
install(FILES "${PROJECT_BINARY_DIR}/course/run/frob.pch" "${PROJECT_BINARY_DIR}/course/run/install/frob-headers.yaml"
  DESTINATION "${frob_libdir}")
install(DIRECTORY "${PROJECT_BINARY_DIR}/course/examples/" DESTINATION "${frob_libdir}/examples" FILES_MATCHING PATTERN "*.so")

# Data and sources. The assignments' reference solutions stay in the source tree, with the
# instructors: an installed frob is also on the students' machines.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/worlds/data/" DESTINATION "${frob_datadir}/worlds")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/course/examples/" DESTINATION "${frob_datadir}/examples")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/assignments/" DESTINATION "${frob_datadir}/assignments" PATTERN "solution.cpp" EXCLUDE)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/render/models/" DESTINATION "${frob_datadir}/models")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/course/template/" DESTINATION "${frob_datadir}/template")
file(CONFIGURE OUTPUT "${PROJECT_BINARY_DIR}/install-version" CONTENT "${PROJECT_VERSION}\n")
install(FILES "${PROJECT_BINARY_DIR}/install-version" DESTINATION "${frob_datadir}" RENAME version)

# The Debian package: the same files under /usr; Depends lists what the programs load and what a
# controller is compiled with (clang, the C++ library's headers, Eigen).
set(CPACK_PACKAGE_NAME frob-sandbox)
set(CPACK_PACKAGE_VENDOR "Frob Sandbox")
set(CPACK_PACKAGE_CONTACT "Frob Sandbox maintainers <frob-sandbox@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION "Write robot controllers in Frob, a functional-reactive language embedded in C++20, run them on a simulated robot in a Box2D world with a debug video, and grade them.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION education)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "libc6, libstdc++6, libgcc-s1, zlib1g, libbox2d2, libassimp5, libdraco7, libminizip1, libtomlplusplus3, libpng16-16, libfreetype6, fonts-dejavu-core, libosmesa6, libavcodec59, libavformat59, libavutil57, libswscale6, libzip4, libseccomp2, libssl3, clang-16, libstdc++-12-dev, libeigen3-dev, libclang-rt-16-dev, binutils")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "cmake, ninja-build, libgtest-dev, clangd-16")  # the student project template; frob init's editor completion
set(CPACK_GENERATOR DEB)
include(CPack)
