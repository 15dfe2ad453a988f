#!/usr/bin/env bash
# Installs the exact Debian 12 packages sinew builds on, only when one is missing.
# Idempotent: a second run installs nothing and takes about a second.
set -euo pipefail

packages=(
  build-essential cmake pkg-config ccache
  coinor-libipopt-dev      # Ipopt 3.11.9 with MUMPS
  libeigen3-dev            # Eigen 3.4
  libsuitesparse-dev       # CHOLMOD, UMFPACK (SuiteSparse 5.12)
  libnlopt-cxx-dev         # NLopt 2.7.1, C++ interface
  catch2                   # Catch2 2.13
  libopenblas0-pthread libopenblas-dev   # the BLAS in use (wins the libblas.so.3 alternative)
  nlohmann-json3-dev       # JSON
  libcli11-dev             # command line parsing
  libtet1.5-dev            # TetGen 1.5: tetrahedralization of closed surfaces
  libcgal-dev              # CGAL 5.5 (header-only): collision bodies' closest points and inside tests
  libopenvdb-dev           # OpenVDB 10 (with oneTBB): level set collision bodies (.vdb, meshToLevelSet)
  python3                  # an independent XML parser for the VTU writer's test
  gnuplot-nox              # sinew compare's plots (PNG and SVG by its cairo terminals; no X)
  python3-matplotlib       # scripts/plot_damage.py: an MPM run's damage field as a PNG (with numpy)
  libpetsc-real-dev        # PETSc 3.18 with OpenMPI and hypre: the petsc-* linear solvers
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y --no-install-recommends "${missing[@]}"
