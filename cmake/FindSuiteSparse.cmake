# Finds CHOLMOD and UMFPACK of SuiteSparse 5.x, which ships neither CMake
# config nor pkg-config files. Defines SuiteSparse::cholmod and
# SuiteSparse::umfpack (each records its own amd/colamd/metis/blas links).
find_path(SuiteSparse_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(SuiteSparse_CHOLMOD_LIBRARY cholmod)
find_library(SuiteSparse_UMFPACK_LIBRARY umfpack)

if(SuiteSparse_INCLUDE_DIR AND EXISTS "${SuiteSparse_INCLUDE_DIR}/SuiteSparse_config.h")
  file(STRINGS "${SuiteSparse_INCLUDE_DIR}/SuiteSparse_config.h" _ss_version_lines
       REGEX "#define SUITESPARSE_(MAIN|SUB|SUBSUB)_VERSION")
  foreach(part MAIN SUB SUBSUB)
    string(REGEX REPLACE ".*SUITESPARSE_${part}_VERSION[ \t]+([0-9]+).*" "\\1" _ss_${part} "${_ss_version_lines}")
  endforeach()
  set(SuiteSparse_VERSION "${_ss_MAIN}.${_ss_SUB}.${_ss_SUBSUB}")
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse
  REQUIRED_VARS SuiteSparse_INCLUDE_DIR SuiteSparse_CHOLMOD_LIBRARY SuiteSparse_UMFPACK_LIBRARY
  VERSION_VAR SuiteSparse_VERSION)

if(SuiteSparse_FOUND)
  foreach(component cholmod umfpack)
    string(TOUPPER ${component} _upper)
    if(NOT TARGET SuiteSparse::${component})
      add_library(SuiteSparse::${component} UNKNOWN IMPORTED)
      set_target_properties(SuiteSparse::${component} PROPERTIES
        IMPORTED_LOCATION "${SuiteSparse_${_upper}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_INCLUDE_DIR}")
    endif()
  endforeach()
endif()
mark_as_advanced(SuiteSparse_INCLUDE_DIR SuiteSparse_CHOLMOD_LIBRARY SuiteSparse_UMFPACK_LIBRARY)
