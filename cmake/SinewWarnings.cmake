# Warnings for sinew's own code only; dependencies come in as -isystem.
add_library(sinew_warnings INTERFACE)
add_library(sinew::warnings ALIAS sinew_warnings)
target_compile_options(sinew_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
  $<$<BOOL:${SINEW_WERROR}>:-Werror>)
# GCC 12 with AVX (SINEW_AVX2) reports Eigen's packet loads in assignments of
# 3-vectors to dynamic-size blocks as out of bounds: the packet branch it
# analyses only runs for sizes of four or more (a known false positive).
if(SINEW_AVX2 AND SINEW_MACHINE_HAS_AVX2 AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(sinew_warnings INTERFACE -Wno-array-bounds)
endif()
