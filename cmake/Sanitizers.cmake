# OCEANGLOBE_SANITIZE=ON builds every target (C and C++, compile and link) with AddressSanitizer
# and UBSan; any UB report aborts the test. scripts/test.sh uses it for build-asan/ (the data
# reader tests); docs/data.md.
option(OCEANGLOBE_SANITIZE "Build with AddressSanitizer and UBSan (-fno-sanitize-recover)" OFF)
if(OCEANGLOBE_SANITIZE)
  if(OCEANGLOBE_FUZZ)
    message(FATAL_ERROR "OCEANGLOBE_FUZZ already instruments with ASan/UBSan; use one of them")
  endif()
  add_compile_options("$<$<COMPILE_LANGUAGE:C,CXX>:-fsanitize=address,undefined>"
                      "$<$<COMPILE_LANGUAGE:C,CXX>:-fno-omit-frame-pointer>"
                      "$<$<COMPILE_LANGUAGE:C,CXX>:-fno-sanitize-recover=undefined>")
  add_link_options(-fsanitize=address,undefined)
endif()
