#pragma once
// Derivatives of a quasistatic equilibrium in the parameters that set it
// (seed 000 §3): the muscle activations, which change the forces (§3.1), and
// the prescribed motions of bone-attached nodes, which move x^C (§3.3–3.4).
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/solvers/linear/linear_solver.hpp"

#include <memory>
#include <string>

namespace sinew {

/// How p parameters θ enter the equilibrium, one column per parameter, rows
/// over all coordinates (node-major):
///   gradient_change    ∂(∇E)/∂θ at a fixed configuration: −f_i of an
///                      activation (§2.1, eq. 4); rows of prescribed
///                      coordinates are not read;
///   prescribed_motion  ∂x^C/∂θ (§3.3: ∂M/∂θ X + ∂t/∂θ for the jaw); rows of
///                      free coordinates are not read.
/// Either may have zero columns (the parameter has no such effect).
struct ParameterDirections {
    Eigen::MatrixXd gradient_change;
    Eigen::MatrixXd prescribed_motion;
    /// p, after checking that both matrices agree (InputError otherwise).
    int count(int num_coordinates) const;
};

/// The equilibrium's Hessian factorized once, then ∂x/∂θ for any number of
/// parameters (one factorization, many right-hand sides) or wᵀ∂x/∂θ by one
/// adjoint solve. At an equilibrium ∇_U E(x^U, x^C; θ) = 0 for all θ, so
///
///     H_UU ∂x^U/∂θ = −(∂(∇_U E)/∂θ + H_UC ∂x^C/∂θ)          (eq. 6 and 9)
///
/// with H = ∇²E the exact (unprojected) Hessian at the equilibrium, H_UU its
/// free block and H_UC the free–prescribed block.
class EquilibriumSensitivities {
public:
    /// Assembles H at `configuration` (all coordinates; an equilibrium of
    /// `problem`, whose prescribed values it must hold) and factorizes H_UU:
    /// CHOLMOD, or MUMPS's LDLᵀ when H_UU is not positive definite. A singular
    /// H_UU leaves ok() false with failure() saying so. InputError for a
    /// problem that does not eliminate its Dirichlet coordinates or has
    /// constraint sets, or a configuration of the wrong size.
    EquilibriumSensitivities(QuasistaticProblem& problem, const Eigen::VectorXd& configuration);
    ~EquilibriumSensitivities();

    bool ok() const { return failure_.empty(); }
    const std::string& failure() const { return failure_; }

    /// ∂x/∂θ over all coordinates: ∂x^C/∂θ on prescribed rows, the solution of
    /// eq. 6/9 on free rows. std::logic_error when !ok().
    Eigen::MatrixXd derivatives(const ParameterDirections& directions);

    /// wᵀ ∂x/∂θ (p entries) by one solve: H_UU μ = w_U, then
    /// w_Cᵀ ∂x^C/∂θ − μᵀ(∂(∇_U E)/∂θ + H_UC ∂x^C/∂θ). std::logic_error when !ok().
    Eigen::VectorXd adjoint_gradient(const Eigen::VectorXd& w, const ParameterDirections& directions);

    /// Factorizations and solves done so far.
    const LinearSolverStats& linear_stats() const;

private:
    /// −(g_U + H_UC m_C) for the columns of `directions`: the right-hand sides.
    Eigen::MatrixXd right_hand_sides(const ParameterDirections& directions) const;
    void require_ok() const;

    QuasistaticProblem& problem_;
    int num_coordinates_;
    std::unique_ptr<LinearSolver> solver_;
    SparseMatrix free_prescribed_;  ///< H_UC as (free variables) × (all coordinates), nonzero on prescribed columns only
    std::string failure_;
};

} // namespace sinew
