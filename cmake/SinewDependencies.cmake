# The Debian 12 packages sinew builds on (scripts/setup.sh installs them).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(PkgConfig REQUIRED)
pkg_check_modules(Ipopt REQUIRED IMPORTED_TARGET ipopt)
# NLopt ships a C and a C++ config that both define package NLopt: pin the C++ one.
find_package(NLopt 2.7 CONFIG REQUIRED HINTS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/nlopt_cxx)
find_package(SuiteSparse 5 REQUIRED)
