#pragma once
#include "sinew/solvers/linear/linear_solver.hpp"
#include "sinew/solvers/newton/pattern_matrix.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sinew {

/// Ipopt's inertia-correction schedule (Wächter & Biegler 2006, §3.1), with
/// its default constants, as the state carried from one iteration to the next.
struct InertiaCorrection {
    double first_delta_w = 1e-4;    ///< δ̄w⁰: the first δw when none was needed last time
    double min_delta_w = 1e-20;     ///< δ̄w_min
    double max_delta_w = 1e40;      ///< δ̄w_max: beyond it the factorization has failed
    double decrease = 1.0 / 3.0;    ///< κw⁻: the next first try is κw⁻ × the last δw
    double increase = 8.0;          ///< κw⁺
    double first_increase = 100.0;  ///< κ̄w⁺: growth while no δw was needed last time
    double delta_c = 1e-8;          ///< δc on the constraint block when K is singular
    double last_delta_w = 0.0;      ///< δw of the last successful factorization
};

/// The shift after `shift` in RegularizedFactorization::solve_shifted's
/// sequence: 1e-8·diagonal_scale after 0, then ten times the last; 0 past 1e20.
double next_shift(double shift, double diagonal_scale);

/// How one try at an SPD solve ended.
enum class ShiftedSolve { solved, indefinite, failed };

/// One factorization attempt: the regularization tried and what it gave.
struct FactorizationAttempt {
    double delta_w = 0.0;
    double delta_c = 0.0;
    LinearStatus status = LinearStatus::failed;
    Inertia inertia;
};

/// Factorizes a matrix plus a regularization, raising the regularization
/// until the factorization succeeds with the required inertia (DESIGN.md,
/// "Solvers"), and keeps the count and time of every factorization and solve.
class RegularizedFactorization {
public:
    explicit RegularizedFactorization(std::unique_ptr<LinearSolver> solver);

    /// SPD systems, one try: factors A + shift·I (the shift is added to A)
    /// and solves x = (A + shift·I)⁻¹ b. `indefinite` when the Cholesky
    /// rejects the matrix (indefinite, or singular by round-off) or an
    /// iterative solver's CG meets non-positive curvature; `failed` for any
    /// other failure (failure() says why).
    ShiftedSolve attempt_shifted(PatternMatrix& A, double shift, const Eigen::VectorXd& b, Eigen::VectorXd& x);

    /// attempt_shifted from `shift` (0: none), raising the shift while the
    /// matrix is found indefinite: 1e-8·diagonal_scale first, then ten times
    /// more each time, up to 1e20. `shift` goes out as the one that worked.
    /// False (failure() says why) when no shift works.
    bool solve_shifted(PatternMatrix& A, double& shift, double diagonal_scale, const Eigen::VectorXd& b,
                       Eigen::VectorXd& x);

    /// Symmetric indefinite KKT systems [H + δw I, Jᵀ; J, −δc I]: `assemble`
    /// fills K for (δw, δc); accepted when the inertia is (n, m, 0).
    /// Ipopt's schedule: δw = 0 first; then κw⁻·(last δw) or δ̄w⁰; then
    /// ×κw⁺ (×κ̄w⁺ while no δw was needed before); δc > 0 once K is singular
    /// or has fewer than m negative eigenvalues (J rank-deficient up to round-off),
    /// dropped again when the accepted δw alone gives the inertia (the
    /// singularity was H's, not J's). attempts().back() is the factorization in use.
    /// Needs a solver that reports inertia. False past δ̄w_max.
    bool factorize_with_inertia(const std::function<const SparseMatrix&(double delta_w, double delta_c)>& assemble,
                                int n, int m, InertiaCorrection& schedule);

    /// x = K⁻¹ b with the last factorization; false (failure() says why) when
    /// the solve fails or gives a non-finite x.
    bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);

    const std::vector<FactorizationAttempt>& attempts() const { return attempts_; }  ///< of the last factorize call
    const std::string& failure() const { return failure_; }
    int factorizations() const { return factorizations_; }
    double factorization_seconds() const { return factorization_s_; }
    double solve_seconds() const { return solve_s_; }
    const LinearSolver& solver() const { return *solver_; }
    /// The near null space of the next matrices, for a solver that
    /// uses_near_null_space() (an algebraic multigrid).
    void set_near_null_space(const NearNullSpace& space) { solver_->set_near_null_space(space); }
    /// The relative residual of the next solves, for an iterative solver.
    void set_tolerance(double relative) { solver_->set_tolerance(relative); }

private:
    LinearStatus factorize_timed(const SparseMatrix& A);

    std::unique_ptr<LinearSolver> solver_;
    std::vector<FactorizationAttempt> attempts_;
    std::string failure_;
    int factorizations_ = 0;
    double factorization_s_ = 0.0;
    double solve_s_ = 0.0;
    LinearStatus solve_status_ = LinearStatus::ok;  ///< what the last solve() reported
};

} // namespace sinew
