#include "sinew/solvers/newton/factorization_reuse.hpp"

#include "sinew/solvers/newton/preconditioned_cg.hpp"

#include <chrono>

namespace sinew {

using Eigen::VectorXd;

FactorizationReuse::FactorizationReuse(RegularizedFactorization& factorization, ReuseSettings settings)
    : factorization_(factorization), settings_(settings)
{
}

bool FactorizationReuse::solve(const SparseMatrix& lower, double shift, const VectorXd& b, double eta, VectorXd& d)
{
    found_indefinite_ = false;
    if (!kept_)
        return false;
    if (backoff_.steps_to_skip > 0) {
        --backoff_.steps_to_skip;
        ++skipped_steps_;
        return false;
    }
    const auto start = std::chrono::steady_clock::now();
    auto multiply = [&](const VectorXd& v, VectorXd& product) {
        product.noalias() = lower.selfadjointView<Eigen::Lower>() * v;  // A v
        if (shift > 0.0)
            product += shift * v;  // + σ v
    };
    auto precondition = [&](const VectorXd& r, VectorXd& z) { return factorization_.solve(r, z); };  // z = A₀⁻¹ r
    const CgOutcome outcome = preconditioned_cg(multiply, precondition, b, eta, settings_.max_cg_iterations, d);
    cg_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    cg_iterations_ += outcome.iterations;
    if (outcome.status == CgStatus::converged) {
        ++reused_steps_;
        backoff_.refusals_in_row = 0;
        return true;
    }
    ++refused_steps_;
    found_indefinite_ = outcome.status == CgStatus::negative_curvature;
    if (!found_indefinite_)
        back_off();
    return false;
}

void FactorizationReuse::back_off()
{
    ++backoff_.refusals_in_row;
    // 2^(k−3) − 1 after the k-th refusal, k ≥ 3: 0, 1, 3, 7, then kMaxSkippedSteps = 2⁴ − 1
    const int doublings = backoff_.refusals_in_row - kRefusalsBeforeBackoff;
    backoff_.steps_to_skip = doublings < 0 ? 0 : doublings >= 4 ? kMaxSkippedSteps : (1 << doublings) - 1;
}

} // namespace sinew
