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

/// OpenBLAS held at one thread while this object lives, then set back to
/// the count it had: for code that runs on one core but calls BLAS on
/// long vectors (PETSc's vector operations in its CG), where OpenBLAS would
/// wake its other threads for every daxpy and ddot and leave them spinning
/// (sched_yield) between calls, on cores the process's other threads need.
class SingleThreadedBlas {
public:
    SingleThreadedBlas();
    ~SingleThreadedBlas();
    SingleThreadedBlas(const SingleThreadedBlas&) = delete;
    SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;

private:
    int previous_;  ///< OpenBLAS's count before; −1 when the BLAS is not OpenBLAS
};

} // namespace sinew
