#!/usr/bin/env bash
# Installs the Debian (bookworm) packages cgcm needs to build, test and plot.
# Idempotent: packages already present are skipped, so `make demo` / `make test`
# can call it on every run. Needs root (or sudo) only when something is missing.
#
#   install-deps.sh [--peers]
#   --peers: also dolfinx (python3-dolfinx, about 120 packages), the peer code
#            of `make peers` (bench/peers/); not needed to build or test cgcm.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ccache pkg-config
  # MPI (Trilinos 13.2 on Debian is MPI-enabled)
  libopenmpi-dev openmpi-bin
  # Trilinos: the whole set; the CMake configs of the individual -dev packages
  # include one another's, so a partial set fails at configure time
  trilinos-all-dev
  # libraries Trilinos' CMake config links by absolute path without depending on them
  libptscotch-dev libscotch-dev libmumps-dev libhdf5-openmpi-dev zlib1g-dev
  libblas-dev liblapack-dev
  # the BLAS behind MUMPS' dense kernels: single-threaded OpenBLAS takes over
  # libblas.so.3 from the reference BLAS through Debian's alternatives (2D
  # level-2 deck: factorisations 2.8 times faster; doc/performance.md), and
  # starts no threads to compete with the MPI ranks
  libopenblas0-serial
  # geometry, meshing, output
  libcgal-dev libgmp-dev libmpfr-dev libgmsh-dev libexodusii-dev libnetcdf-dev
  # Boost.Math (root finding in the fold location)
  libboost-dev
  # tests and plots
  googletest libgtest-dev python3 python3-numpy python3-matplotlib python3-netcdf4
)

case "${1:-}" in
  "") ;;
  --peers) packages+=(python3-dolfinx) ;;
  *) echo "install-deps: unknown option \"$1\"; allowed: --peers" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${#missing[@]} missing packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
