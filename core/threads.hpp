#pragma once

namespace sinew {

/// The cores this process may run on: the size of its CPU affinity mask
/// (taskset, cgroups' cpusets), at least 1.
int available_cores();

/// The one thread setting (DESIGN.md, "Threads"): OpenMP's parallel regions
/// (assembly) and OpenBLAS's threads (CHOLMOD's and MUMPS's dense blocks)
/// both get `count`. They never run at once (assembly and factorization
/// alternate), so `count` ≤ available_cores() keeps the cores from being
/// oversubscribed. InputError for a count below 1 or above available_cores().
void set_threads(int count);

/// The count set_threads() set last; available_cores() before any call.
int threads();

/// OpenBLAS's own thread count (openblas_get_num_threads), or −1 when the
/// BLAS in the process is not OpenBLAS.
int blas_threads();

} // namespace sinew
