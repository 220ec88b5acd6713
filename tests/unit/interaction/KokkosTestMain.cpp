// GoogleTest main for the interaction tests: the kernels run through Kokkos
// (Views, parallel_for), which needs one initialisation per process.
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
