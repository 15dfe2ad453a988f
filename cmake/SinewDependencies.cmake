# The Debian 12 packages sinew builds on (scripts/setup.sh installs them).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(PkgConfig REQUIRED)
pkg_check_modules(Ipopt REQUIRED IMPORTED_TARGET ipopt)
# NLopt ships a C and a C++ config that both define package NLopt: pin the C++ one.
find_package(NLopt 2.7 CONFIG REQUIRED HINTS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/nlopt_cxx)
find_package(SuiteSparse 5 REQUIRED)
# MUMPS 5.5, sequential (libmumps-seq-dev, pulled in by Ipopt's dev package,
# whose libipopt links the same libdmumps_seq): the KKT solvers' LDLᵀ with inertia.
find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
find_library(MUMPS_LIBRARY dmumps_seq REQUIRED)
find_library(MUMPS_COMMON_LIBRARY mumps_common_seq REQUIRED)
add_library(MUMPS::dmumps_seq UNKNOWN IMPORTED)
set_target_properties(MUMPS::dmumps_seq PROPERTIES IMPORTED_LOCATION "${MUMPS_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${MUMPS_INCLUDE_DIR}" INTERFACE_LINK_LIBRARIES "${MUMPS_COMMON_LIBRARY}")

# TetGen 1.5 (libtet1.5-dev): no pkg-config or CMake config in Debian.
find_path(TETGEN_INCLUDE_DIR tetgen.h REQUIRED)
find_library(TETGEN_LIBRARY tet REQUIRED)
add_library(TetGen::tet UNKNOWN IMPORTED)
set_target_properties(TetGen::tet PROPERTIES IMPORTED_LOCATION "${TETGEN_LIBRARY}"
                      INTERFACE_INCLUDE_DIRECTORIES "${TETGEN_INCLUDE_DIR}")
find_package(OpenMP REQUIRED)
# libcgal-dev: CGAL 5.5, header-only (with GMP and MPFR); collision bodies
# (bodies/: AABB tree closest points, Side_of_triangle_mesh).
find_package(CGAL 5.5 REQUIRED)
# libopenvdb-dev: OpenVDB 10 (with oneTBB): level set collision bodies
# (bodies/level_set_body). Debian's FindOpenVDB.cmake asks for Boost
# components the package does not pull in, so the library is found directly.
find_path(OPENVDB_INCLUDE_DIR openvdb/openvdb.h REQUIRED)
find_library(OPENVDB_LIBRARY openvdb REQUIRED)
find_package(TBB CONFIG REQUIRED)
# Imath's half floats, which OpenVDB's file I/O uses (found directly too: Debian's
# ImathConfig.cmake names a Python module the package does not ship).
find_library(IMATH_LIBRARY Imath-3_1 REQUIRED)
add_library(OpenVDB::openvdb UNKNOWN IMPORTED)
set_target_properties(OpenVDB::openvdb PROPERTIES IMPORTED_LOCATION "${OPENVDB_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${OPENVDB_INCLUDE_DIR}" INTERFACE_LINK_LIBRARIES "TBB::tbb;${IMATH_LIBRARY}")
# nlohmann-json3-dev: header-only; scene files and the CLI's JSON.
find_package(nlohmann_json 3 REQUIRED)

# PETSc 3.18 (libpetsc-real-dev, with OpenMPI and hypre): the petsc-* linear
# solvers (solvers/linear/petsc_solver.hpp). Optional: without it the build
# goes on, those solvers are not listed, and asking for one names the package.
option(SINEW_WITH_PETSC "Build the petsc-* linear solvers when PETSc is found" ON)
set(SINEW_HAVE_PETSC OFF)
if(SINEW_WITH_PETSC)
  pkg_check_modules(PETSc QUIET IMPORTED_TARGET PETSc)
  if(PETSc_FOUND)
    # PETSc's headers include mpi.h; the MPI C library without its C++ bindings.
    set(MPI_CXX_SKIP_MPICXX ON)
    find_package(MPI COMPONENTS CXX)
  endif()
  if(PETSc_FOUND AND MPI_CXX_FOUND)
    set(SINEW_HAVE_PETSC ON)
    message(STATUS "PETSc ${PETSc_VERSION} found: the petsc-* linear solvers are built")
  else()
    message(STATUS "PETSc not found: the petsc-* linear solvers are left out (bash scripts/setup.sh installs libpetsc-real-dev)")
  endif()
endif()
