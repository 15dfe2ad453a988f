#include "sinew/core/threads.hpp"

#include "sinew/core/input_error.hpp"

#include <dlfcn.h>
#include <omp.h>
#include <sched.h>

#include <string>

namespace sinew {
namespace {

int thread_setting = 0;  ///< 0: not set yet

/// OpenBLAS's entry points, looked up in the running process: libsinew links
/// the reference BLAS interface (libblas.so.3), which Debian's alternative
/// points at OpenBLAS (docs/solvers.md, "Which BLAS").
template <typename Function>
Function* openblas(const char* name)
{
    return reinterpret_cast<Function*>(dlsym(RTLD_DEFAULT, name));
}

} // namespace

int available_cores()
{
    cpu_set_t mask;
    CPU_ZERO(&mask);
    if (sched_getaffinity(0, sizeof mask, &mask) != 0)
        return 1;
    return CPU_COUNT(&mask) > 0 ? CPU_COUNT(&mask) : 1;
}

void set_threads(int count)
{
    const int cores = available_cores();
    if (count < 1 || count > cores)
        throw InputError("--threads " + std::to_string(count) + " is invalid; this process may use " +
                         std::to_string(cores) + " core" + (cores == 1 ? "" : "s") + ", so 1 to " +
                         std::to_string(cores));
    omp_set_num_threads(count);
    if (auto* set = openblas<void(int)>("openblas_set_num_threads"))
        set(count);
    thread_setting = count;
}

int threads()
{
    return thread_setting > 0 ? thread_setting : available_cores();
}

int blas_threads()
{
    auto* get = openblas<int()>("openblas_get_num_threads");
    return get ? get() : -1;
}

SingleThreadedBlas::SingleThreadedBlas() : previous_(blas_threads())
{
    if (previous_ > 1)
        openblas<void(int)>("openblas_set_num_threads")(1);
}

SingleThreadedBlas::~SingleThreadedBlas()
{
    if (previous_ > 1)
        openblas<void(int)>("openblas_set_num_threads")(previous_);
}

} // namespace sinew
