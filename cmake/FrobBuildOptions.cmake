# Compiler settings shared by every target of ours, carried by one interface target.
find_program(FROB_CCACHE ccache)
if(FROB_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER "${FROB_CCACHE}")
  set(CMAKE_C_COMPILER_LAUNCHER "${FROB_CCACHE}")
endif()

if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE RelWithDebInfo CACHE STRING "Build type" FORCE)
endif()

add_library(frob_build_options INTERFACE)
add_library(frob::build_options ALIAS frob_build_options)
target_compile_features(frob_build_options INTERFACE cxx_std_20)
target_compile_options(frob_build_options INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
  # Definition structs are filled with designated initializers; omitted fields keep their defaults.
  -Wno-missing-field-initializers
  # DWARF 4 where there is debug info: Debian 12's valgrind (callgrind, memcheck) cannot read clang's
  # DWARF 5. (-gdwarf-4 would also turn full debug info on, over a preset's -gline-tables-only.)
  $<$<CXX_COMPILER_ID:Clang>:-fdebug-default-version=4>
  # A recursive task (the paper's runAround) calls itself lazily, inside its coroutine: not a loop.
  $<$<CXX_COMPILER_ID:Clang>:-Wno-infinite-recursion>
  # Deterministic floating point: no fused multiply-add contraction (as Box2D does).
  -ffp-contract=off
  $<$<BOOL:${FROB_WERROR}>:-Werror>)

# Sanitizers apply to the whole build so that every test runs under them.
if(FROB_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()

# frob_add_library(name SOURCES ... PUBLIC_LINKS ... PRIVATE_LINKS ...): target frob_<name> with alias
# frob::<name> and public headers under include/ beside its CMakeLists.txt. With no sources yet it
# is an interface target that carries its headers and dependencies.
function(frob_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_LINKS;PRIVATE_LINKS" ${ARGN})
  if(NOT ARG_SOURCES)
    add_library(frob_${name} INTERFACE)
    add_library(frob::${name} ALIAS frob_${name})
    target_include_directories(frob_${name} INTERFACE "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>")
    target_link_libraries(frob_${name} INTERFACE ${ARG_PUBLIC_LINKS} ${ARG_PRIVATE_LINKS})
    return()
  endif()
  add_library(frob_${name} ${ARG_SOURCES})
  add_library(frob::${name} ALIAS frob_${name})
  # Installed, a library's headers are in the prefix's include folder (cmake/FrobInstall.cmake).
  target_include_directories(frob_${name} PUBLIC "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>" "$<INSTALL_INTERFACE:include>")
  target_link_libraries(frob_${name} PUBLIC ${ARG_PUBLIC_LINKS} PRIVATE frob::build_options ${ARG_PRIVATE_LINKS})
  set_target_properties(frob_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

# frob_configure_depends_on_folder(dir): CMake runs again when a file is added to or removed from `dir`
# (which changes the folder's time), for a file(GLOB) over it. Unlike CONFIGURE_DEPENDS, whose check
# runs at every build, a build with nothing to do then does nothing.
function(frob_configure_depends_on_folder dir)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${dir}")
endfunction()
