// cholmod_factorize: a standalone CHOLMOD supernodal Cholesky factorization
// of a symmetric matrix read from a Matrix Market file (`sinew hessian`
// writes one), with each fill-reducing ordering CHOLMOD offers, for
// comparing sinew's factorization time with CHOLMOD's own (docs/benchmarks.md).
// It uses CHOLMOD alone, not libsinew; OpenBLAS's threads are
// OPENBLAS_NUM_THREADS (default: every core).
//
//   cholmod_factorize matrix.mtx [repeats]
//
// prints, per ordering: the analysis time, nnz(L), the flop count, and the
// fastest and median of `repeats` numeric factorizations.
#include <cholmod.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Ordering {
    const char* name;
    int nmethods;  // 0: CHOLMOD's default choice (AMD, then METIS when AMD fills much)
    int method;
};

void factorize_with(cholmod_sparse* A, const Ordering& ordering, int repeats)
{
    cholmod_common common;
    cholmod_start(&common);
    common.supernodal = CHOLMOD_SUPERNODAL;
    common.nmethods = ordering.nmethods;
    if (ordering.nmethods == 1) {
        common.method[0].ordering = ordering.method;
        common.postorder = 1;
    }
    auto start = std::chrono::steady_clock::now();
    cholmod_factor* L = cholmod_analyze(A, &common);
    const double analysis = seconds_since(start);
    if (L == nullptr) {
        std::printf("| %s | analysis failed (status %d) | | | | |\n", ordering.name, common.status);
        cholmod_finish(&common);
        return;
    }
    std::vector<double> times;
    for (int k = 0; k < repeats; ++k) {
        start = std::chrono::steady_clock::now();
        cholmod_factorize(A, L, &common);
        times.push_back(seconds_since(start));
        if (common.status != CHOLMOD_OK) {
            std::printf("| %s | factorization failed (status %d) | | | | |\n", ordering.name, common.status);
            break;
        }
    }
    std::sort(times.begin(), times.end());
    std::printf("| %s | %.3f | %.0f | %.3g | %.4f | %.4f |\n", ordering.name, analysis, common.lnz, common.fl,
                times.front(), times[times.size() / 2]);
    cholmod_free_factor(&L, &common);
    cholmod_finish(&common);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: cholmod_factorize matrix.mtx [repeats]\n");
        return 2;
    }
    const int repeats = argc == 3 ? std::atoi(argv[2]) : 5;
    if (repeats < 1) {
        std::fprintf(stderr, "cholmod_factorize: repeats must be at least 1\n");
        return 2;
    }
    FILE* file = std::fopen(argv[1], "r");
    if (file == nullptr) {
        std::fprintf(stderr, "cholmod_factorize: cannot open %s\n", argv[1]);
        return 2;
    }
    cholmod_common common;
    cholmod_start(&common);
    cholmod_sparse* A = cholmod_read_sparse(file, &common);
    std::fclose(file);
    if (A == nullptr || A->stype == 0) {
        std::fprintf(stderr, "cholmod_factorize: %s is not a symmetric Matrix Market matrix\n", argv[1]);
        return 2;
    }
    std::printf("%s: %zu × %zu, %zu stored entries, %d repeats\n\n", argv[1], A->nrow, A->ncol,
                static_cast<size_t>(cholmod_nnz(A, &common)), repeats);
    std::printf("| ordering | analysis (s) | nnz(L) | flops | fastest factorization (s) | median (s) |\n"
                "|---|---:|---:|---:|---:|---:|\n");
    const Ordering orderings[] = {{"default (as sinew)", 0, 0},
                                  {"AMD", 1, CHOLMOD_AMD},
                                  {"METIS", 1, CHOLMOD_METIS},
                                  {"NESDIS", 1, CHOLMOD_NESDIS}};
    for (const Ordering& ordering : orderings)
        factorize_with(A, ordering, repeats);
    cholmod_free_sparse(&A, &common);
    cholmod_finish(&common);
    return 0;
}
