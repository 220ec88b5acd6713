# Third-party dependencies, all from Debian bookworm packages (scripts/install-deps.sh).

# Debian's Trilinos 13.2 is MPI-enabled but exports no MPI include directories.
find_package(MPI REQUIRED COMPONENTS CXX)

find_package(Trilinos 13.2 REQUIRED COMPONENTS
  Teuchos Kokkos Tpetra Thyra ThyraTpetraAdapters NOX Stratimikos Belos Ifpack2 Amesos2 MueLu Zoltan2)

# Kokkos core only: what the physics kernels may see (KOKKOS_INLINE_FUNCTION, Kokkos::View).
add_library(cgcm_kokkos INTERFACE)
target_include_directories(cgcm_kokkos SYSTEM INTERFACE ${Trilinos_INCLUDE_DIRS})
target_link_libraries(cgcm_kokkos INTERFACE trilinos_kokkoscore MPI::MPI_CXX)

# Teuchos only: parameter lists and dense LAPACK for packages that need no distributed objects.
add_library(cgcm_teuchos INTERFACE)
target_include_directories(cgcm_teuchos SYSTEM INTERFACE ${Trilinos_INCLUDE_DIRS})
target_link_libraries(cgcm_teuchos INTERFACE trilinos_teuchosparameterlist trilinos_teuchoscore trilinos_teuchoscomm trilinos_teuchosnumerics
                      trilinos_teuchosparser MPI::MPI_CXX)

# The whole Trilinos stack: assembly, solver and io only.
add_library(cgcm_trilinos INTERFACE)
target_include_directories(cgcm_trilinos SYSTEM INTERFACE ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
target_link_libraries(cgcm_trilinos INTERFACE ${Trilinos_LIBRARIES} ${Trilinos_TPL_LIBRARIES} MPI::MPI_CXX)

find_package(GTest 1.12 REQUIRED)
find_package(Python3 COMPONENTS Interpreter)

# CGAL (header-only here: AABB trees on a floating-point kernel).
find_package(CGAL 5.5 REQUIRED)
# Optional for now; required by the packages that use them.
find_path(GMSH_INCLUDE_DIR gmsh.h)
find_library(GMSH_LIBRARY gmsh)
find_path(EXODUS_INCLUDE_DIR exodusII.h)
find_library(EXODUS_LIBRARY exoIIv2c)
find_library(NETCDF_LIBRARY netcdf)
# MUMPS (libmumps-dev, double precision, MPI): the "MUMPS" linear solver.
find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
find_library(DMUMPS_LIBRARY dmumps REQUIRED)
find_library(MUMPS_COMMON_LIBRARY mumps_common REQUIRED)
