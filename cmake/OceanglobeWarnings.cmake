# One place for the warning set every oceanglobe target builds with.
add_library(oceanglobe_warnings INTERFACE)
target_compile_options(oceanglobe_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
    -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual
    -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough>
  $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<BOOL:${OCEANGLOBE_WERROR}>>:-Werror>)

# Declares a library for one src/ folder with the project's warnings.
function(oceanglobe_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC} PRIVATE oceanglobe_warnings ${ARG_PRIVATE})
endfunction()

# Declares a module loaded when first needed (core/Plugin.hpp): NAME.so beside the executable,
# from the folder's sources (with core/PluginLog.cpp for og::log), linked to what it wraps but
# to no oceanglobe library. `OWNER`, the folder's library, builds it first: whatever links the
# library can load it.
# The token a module and the program loading it must share (core/Plugin.hpp's Host::abi): the
# version and a random part drawn once per build tree, so that a module of another build (whose
# classes may differ behind the same names) is refused, not called.
if(NOT OCEANGLOBE_PLUGIN_ABI)
  string(RANDOM LENGTH 12 token)
  set(OCEANGLOBE_PLUGIN_ABI "${PROJECT_VERSION}-${token}" CACHE INTERNAL "modules' build token")
endif()
function(oceanglobe_module name)
  cmake_parse_arguments(ARG "" "OWNER" "SOURCES;PRIVATE" ${ARGN})
  add_library(${name} MODULE ${ARG_SOURCES} ${PROJECT_SOURCE_DIR}/src/core/PluginLog.cpp)
  target_compile_definitions(${name} PRIVATE OG_PLUGIN_ABI="${OCEANGLOBE_PLUGIN_ABI}")
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(${name} PRIVATE oceanglobe_warnings ${ARG_PRIVATE})
  set_target_properties(${name} PROPERTIES PREFIX "" LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})
  if(NOT OCEANGLOBE_SANITIZE AND NOT OCEANGLOBE_FUZZ)  # (their runtimes resolve at load)
    target_link_options(${name} PRIVATE -Wl,--no-undefined)  # a missing symbol fails the build, not a run
  endif()
  add_dependencies(${ARG_OWNER} ${name})
endfunction()
