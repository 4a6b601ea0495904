# The public headers are the language's index (issue 15): each is a list of declarations, with the
# machinery (any `namespace detail`) under frob/detail/, and each compiles on its own.
# Run as: cmake -DINCLUDE_DIR=... -DEIGEN_DIR=... -DCXX=... -P public_headers.cmake
file(GLOB headers "${INCLUDE_DIR}/frob/*.hpp")
list(LENGTH headers count)
if(count LESS 20)
  message(FATAL_ERROR "found ${count} public headers in ${INCLUDE_DIR}/frob, expected at least 20")
endif()
foreach(header IN LISTS headers)
  file(STRINGS "${header}" machinery REGEX "namespace detail")
  if(machinery)
    message(SEND_ERROR "${header} defines machinery (${machinery}): move it to frob/detail/")
  endif()
  get_filename_component(name "${header}" NAME)
  execute_process(COMMAND "${CXX}" -std=c++20 -fsyntax-only -x c++ -I${INCLUDE_DIR} -isystem ${EIGEN_DIR} -
                  INPUT_FILE "${header}" RESULT_VARIABLE failed ERROR_VARIABLE errors)
  if(failed)
    message(SEND_ERROR "frob/${name} does not compile on its own:\n${errors}")
  endif()
endforeach()
