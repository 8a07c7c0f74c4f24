/* ----------------------------------------------------------------------
   GRANSPH - granular flow with smoothed particle hydrodynamics in LAMMPS
   Copyright (2026) the GRANSPH developers. This software is distributed
   under the GNU General Public License, version 2 (LICENSE), as LAMMPS is.
------------------------------------------------------------------------- */

// Compiled (never run) by the CUDA:nvcc_compile check: the smallest device code
// in the style of GRANSPH's /kk classes, so a broken CUDA Kokkos install or
// wrong nvcc flags show up here rather than in a style.

#include <Kokkos_Core.hpp>
#include <type_traits>

int main(int argc, char **argv)
{
  int rc = 0;
  Kokkos::initialize(argc, argv);
  {
    const int n = 1000;
    Kokkos::View<double *, Kokkos::CudaSpace> x("x", n);
    static_assert(std::is_same<Kokkos::DefaultExecutionSpace, Kokkos::Cuda>::value,
                  "the CUDA Kokkos must make Cuda the default execution space");

    Kokkos::parallel_for(
        "fill", n, KOKKOS_LAMBDA(const int i) { x(i) = 0.5 * i; });
    double sum = 0.0;
    Kokkos::parallel_reduce(
        "sum", n, KOKKOS_LAMBDA(const int i, double &s) { s += x(i) * x(i); }, sum);
    if (!(sum > 0.0)) rc = 1;
  }
  Kokkos::finalize();
  return rc;
}
