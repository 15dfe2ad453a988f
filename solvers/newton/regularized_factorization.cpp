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

} // namespace

double next_shift(double shift, double diagonal_scale)
{
    const double next = shift == 0.0 ? 1e-8 * diagonal_scale : 10.0 * shift;
    return std::isfinite(next) && next <= 1e20 ? next : 0.0;
}

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

ShiftedSolve RegularizedFactorization::attempt_shifted(PatternMatrix& A, double shift, const Eigen::VectorXd& b,
                                                      Eigen::VectorXd& x)
{
    attempts_.clear();
    if (shift > 0.0)
        A.shift_diagonal(shift);
    const LinearStatus status = factorize_timed(A.matrix());
    attempts_.push_back({shift, 0.0, status, solver_->inertia()});
    if (rejected_by_cholesky(status)) {
        failure_ = "factorization failed: " + solver_->last_message();
        return ShiftedSolve::indefinite;
    }
    if (status != LinearStatus::ok) {
        failure_ = "factorization failed: " + solver_->last_message();
        return ShiftedSolve::failed;
    }
    if (solve(b, x))
        return ShiftedSolve::solved;
    return solve_status_ == LinearStatus::not_positive_definite ? ShiftedSolve::indefinite : ShiftedSolve::failed;
}

bool RegularizedFactorization::solve_shifted(PatternMatrix& A, double& shift, double diagonal_scale,
                                             const Eigen::VectorXd& b, Eigen::VectorXd& x)
{
    for (;;) {
        const ShiftedSolve outcome = attempt_shifted(A, shift, b, x);
        if (outcome != ShiftedSolve::indefinite)
            return outcome == ShiftedSolve::solved;
        const double next = next_shift(shift, diagonal_scale);
        if (next == 0.0)
            return false;
        A.shift_diagonal(-shift);  // attempt_shifted adds the shift it is given to A
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
    // δc once K is singular, or has fewer than m negative eigenvalues: with J
    // of full row rank K has at least m (whatever H), so fewer say that J is
    // rank-deficient up to round-off (a zero pivot that came out positive),
    // which no δw can cure.
    const FactorizationAttempt& first = attempts_.back();
    const bool deficient = first.status == LinearStatus::ok && first.inertia.negative < m;
    const double delta_c = singular() || deficient ? schedule.delta_c : 0.0;
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
