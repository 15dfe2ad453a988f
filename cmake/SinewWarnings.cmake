# Warnings for sinew's own code only; dependencies come in as -isystem.
add_library(sinew_warnings INTERFACE)
add_library(sinew::warnings ALIAS sinew_warnings)
target_compile_options(sinew_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
  $<$<BOOL:${SINEW_WERROR}>:-Werror>)
