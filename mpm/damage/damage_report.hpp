#pragma once
// What one damage update did (seed 004 Alg. 3–10), for the run's rows and
// the benchmark.
#include <string>

namespace sinew {

struct DamageReport {
    /// Empty, or the particle whose driving force is not defined (the
    /// particles are then as they were).
    std::string failure;
    int grown = 0;             ///< particles whose d grew
    int capped_at_one = 0;     ///< particles where min(1, ·) acted
    int decrease_refused = 0;  ///< implicit: particles whose grid value fell below d_p, kept at d_p
    int cg_iterations = 0;     ///< implicit: iterations of the damage solve
    double cg_residual = 0.0;  ///< implicit: its ‖c − (A + B)d‖ / ‖c‖
    bool cg_converged = true;  ///< implicit: whether the solve met its tolerance
};

} // namespace sinew
