#include "sinew/solvers/newton/regularized_factorization.hpp"

#include "sinew/core/format_number.hpp"

#include <chrono>
#include <cmath>

namespace sinew {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

bool rejected_by_cholesky(LinearStatus status)
{
    return status == LinearStatus::not_positive_definite || status == LinearStatus::singular;
}

/// The shift after `shift` in factorize_shifted's sequence; 0 past 1e20.
double next_shift(double shift, double diagonal_scale)
{
    const double next = shift == 0.0 ? 1e-8 * diagonal_scale : 10.0 * shift;
    return std::isfinite(next) && next <= 1e20 ? next : 0.0;
}

} // namespace

RegularizedFactorization::RegularizedFactorization(std::unique_ptr<LinearSolver> solver) : solver_(std::move(solver))
{
}

LinearStatus RegularizedFactorization::factorize_timed(const SparseMatrix& A)
{
    const auto start = Clock::now();
    const LinearStatus status = solver_->factorize(A);
    factorization_s_ += seconds_since(start);
    ++factorizations_;
    return status;
}

bool RegularizedFactorization::factorize_shifted(PatternMatrix& A, double& shift, double diagonal_scale)
{
    attempts_.clear();
    if (shift > 0.0)
        A.shift_diagonal(shift);
    LinearStatus status = factorize_timed(A.matrix());
    attempts_.push_back({shift, 0.0, status, solver_->inertia()});
    while (rejected_by_cholesky(status)) {
        const double next = next_shift(shift, diagonal_scale);
        if (next == 0.0)
            break;
        A.shift_diagonal(next - shift);
        shift = next;
        status = factorize_timed(A.matrix());
        attempts_.push_back({shift, 0.0, status, solver_->inertia()});
    }
    if (status == LinearStatus::ok)
        return true;
    failure_ = "factorization failed: " + solver_->last_message();
    return false;
}

bool RegularizedFactorization::solve_shifted(PatternMatrix& A, double& shift, double diagonal_scale,
                                             const Eigen::VectorXd& b, Eigen::VectorXd& x)
{
    for (;;) {
        if (!factorize_shifted(A, shift, diagonal_scale))
            return false;
        if (solve(b, x))
            return true;
        const double next = next_shift(shift, diagonal_scale);
        if (solve_status_ != LinearStatus::not_positive_definite || next == 0.0)
            return false;
        A.shift_diagonal(-shift);  // factorize_shifted adds the shift it is given to A
        shift = next;
    }
}

bool RegularizedFactorization::factorize_with_inertia(
    const std::function<const SparseMatrix&(double delta_w, double delta_c)>& assemble, int n, int m,
    InertiaCorrection& schedule)
{
    attempts_.clear();
    auto attempt = [&](double delta_w, double delta_c) {
        const LinearStatus status = factorize_timed(assemble(delta_w, delta_c));
        const Inertia inertia = solver_->inertia();
        attempts_.push_back({delta_w, delta_c, status, inertia});
        return status == LinearStatus::ok && inertia.positive == n && inertia.negative == m && inertia.zero == 0;
    };
    auto singular = [&] {
        const FactorizationAttempt& last = attempts_.back();
        return last.status == LinearStatus::singular || last.inertia.zero > 0;
    };
    if (attempt(0.0, 0.0)) {
        schedule.last_delta_w = 0.0;
        return true;
    }
    const double delta_c = singular() ? schedule.delta_c : 0.0;
    double delta_w = schedule.last_delta_w == 0.0
                         ? schedule.first_delta_w
                         : std::max(schedule.min_delta_w, schedule.decrease * schedule.last_delta_w);
    const double growth = schedule.last_delta_w == 0.0 ? schedule.first_increase : schedule.increase;
    while (delta_w <= schedule.max_delta_w) {
        if (attempt(delta_w, delta_c)) {
            schedule.last_delta_w = delta_w;
            // A singular K at δw = 0 may owe it to H alone (zero curvature on
            // J's null space), which δw cures: then δc is not needed, and the
            // multipliers of the unperturbed constraint block are kept.
            if (delta_c > 0.0 && !attempt(delta_w, 0.0))
                attempt(delta_w, delta_c);
            return true;
        }
        delta_w *= growth;
    }
    const bool stays_singular = attempts_.back().status == LinearStatus::singular;
    failure_ = "no regularization up to delta_w = 1e40 gives the KKT matrix the inertia (" + std::to_string(n) +
               ", " + std::to_string(m) + ", 0)" +
               (stays_singular ? ": it stays singular (delta_c = " + format_number(delta_c) +
                                     "), so the constraint Jacobian looks rank-deficient (dependent constraints, "
                                     "or more than the variables can meet)"
                               : "; last: " + solver_->last_message());
    return false;
}

bool RegularizedFactorization::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
{
    const auto start = Clock::now();
    const LinearStatus status = solver_->solve(b, x);
    solve_s_ += seconds_since(start);
    solve_status_ = status;
    if (status == LinearStatus::ok && x.allFinite())
        return true;
    failure_ = "linear solve failed: " + solver_->last_message();
    return false;
}

} // namespace sinew
