# Only the transport includes cpp-httplib (README "Layout", server/http/http_transport.cpp): every other
# file of the libraries and programs works on the plain types of http/http_types.h. The transport's own
# headers include it too, so no file outside the transport may include them either. Tests and benchmarks
# are clients of the library and may include it.
# Run: cmake -DSOURCE_DIR=<repository> -P httplib_includes.cmake
cmake_minimum_required(VERSION 3.25)
set(allowed
  server/http/http_transport.cpp
  server/http/transport_stream.h
  server/http/transport_stream.cpp
  server/http/transport_refusals.h
  server/http/transport_refusals.cpp
)
set(found_allowed "")
set(offenders "")
foreach(folder core server render scene engines fuzz)
  file(GLOB_RECURSE sources RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/${folder}/*.h ${SOURCE_DIR}/${folder}/*.cpp
       ${SOURCE_DIR}/${folder}/*.in)
  foreach(source IN LISTS sources)
    file(STRINGS ${SOURCE_DIR}/${source} includes
         REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](httplib|http/transport_stream|http/transport_refusals)\\.h[>\"]")
    if(includes)
      if(source IN_LIST allowed)
        list(APPEND found_allowed ${source})
      else()
        list(APPEND offenders ${source})
      endif()
    endif()
  endforeach()
endforeach()
if(offenders)
  list(JOIN offenders "\n  " lines)
  message(FATAL_ERROR "only the transport may include httplib.h or its transport_*.h; also included by:\n  ${lines}")
endif()
# The check must see the transport itself, or it is looking in the wrong place.
if(NOT "server/http/http_transport.cpp" IN_LIST found_allowed)
  message(FATAL_ERROR "server/http/http_transport.cpp does not include httplib.h: is SOURCE_DIR right?")
endif()
list(LENGTH found_allowed n)
message(STATUS "httplib.h and the transport's headers are included by the transport's files only (${n} of them)")
