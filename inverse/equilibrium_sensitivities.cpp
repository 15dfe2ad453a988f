#include "sinew/inverse/equilibrium_sensitivities.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/solvers/newton/pattern_matrix.hpp"

#include <stdexcept>
#include <vector>

namespace sinew {

int ParameterDirections::count(int num_coordinates) const
{
    const auto check_rows = [&](const Eigen::MatrixXd& m, const char* name) {
        if (m.cols() > 0 && m.rows() != num_coordinates)
            throw InputError(std::string("equilibrium sensitivities: ") + name + " has " + std::to_string(m.rows()) +
                             " rows, expected " + std::to_string(num_coordinates));
    };
    check_rows(gradient_change, "gradient_change");
    check_rows(prescribed_motion, "prescribed_motion");
    if (gradient_change.cols() > 0 && prescribed_motion.cols() > 0 && gradient_change.cols() != prescribed_motion.cols())
        throw InputError("equilibrium sensitivities: gradient_change has " + std::to_string(gradient_change.cols()) +
                         " columns but prescribed_motion " + std::to_string(prescribed_motion.cols()));
    return static_cast<int>(std::max(gradient_change.cols(), prescribed_motion.cols()));
}

namespace {

/// H_UC from the lower triangle of the full Hessian: entries with one free
/// and one prescribed coordinate, as (free variable) × (coordinate).
SparseMatrix free_prescribed_block(const HessianPattern& pattern, const Eigen::VectorXd& values,
                                   const std::vector<int>& variable_of)
{
    std::vector<Eigen::Triplet<double>> entries;
    for (int k = 0; k < pattern.nonzeros(); ++k) {
        const int r = pattern.rows()[k], c = pattern.cols()[k];
        const bool r_free = variable_of[r] >= 0, c_free = variable_of[c] >= 0;
        if (r_free && !c_free)
            entries.emplace_back(variable_of[r], c, values[k]);
        else if (c_free && !r_free)
            entries.emplace_back(variable_of[c], r, values[k]);
    }
    int free = 0;
    for (const int v : variable_of)
        free += v >= 0;
    SparseMatrix block(free, static_cast<int>(variable_of.size()));
    block.setFromTriplets(entries.begin(), entries.end());
    return block;
}

} // namespace

EquilibriumSensitivities::EquilibriumSensitivities(QuasistaticProblem& problem, const Eigen::VectorXd& configuration)
    : problem_(problem), num_coordinates_(problem.potential().num_coordinates())
{
    if (problem.strategy() != DirichletStrategy::eliminate || problem.num_constraints() > 0)
        throw InputError("equilibrium sensitivities: problem '" + problem.name() +
                         "' must eliminate its prescribed coordinates and have no constraint sets");
    if (configuration.size() != num_coordinates_ || !configuration.allFinite())
        throw InputError("equilibrium sensitivities: the configuration has " + std::to_string(configuration.size()) +
                         " coordinates (or a non-finite one), expected " + std::to_string(num_coordinates_));
    // H_UU: the problem's own Hessian on its variables (σ = 1, no constraints, exact).
    const Eigen::VectorXd variables = problem.variables_of(configuration);
    const int n = problem.num_variables();
    Eigen::VectorXd values(problem.hessian_pattern().nonzeros());
    problem.hessian(variables, 1.0, Eigen::VectorXd(), Projection::none, values);
    PatternMatrix H_UU(problem.hessian_pattern(), n);
    H_UU.fill(values);
    // H_UC: the free–prescribed block of the potential's Hessian on all coordinates.
    TotalPotential& E = problem.potential();
    Eigen::VectorXd full_values(E.hessian_pattern().nonzeros());
    E.hessian_values(configuration, Projection::none, full_values);
    std::vector<int> variable_of(num_coordinates_, -1);
    for (int k = 0; k < n; ++k)
        variable_of[problem.free_coordinates()[k]] = k;
    free_prescribed_ = free_prescribed_block(E.hessian_pattern(), full_values, variable_of);

    solver_ = make_linear_solver("cholmod");
    LinearStatus status = solver_->factorize(H_UU.matrix());
    if (status == LinearStatus::not_positive_definite) {
        // An equilibrium that is not a strict minimum: its derivatives exist while H_UU is nonsingular.
        solver_ = make_linear_solver("mumps-ldlt");
        status = solver_->factorize(H_UU.matrix());
        if (status == LinearStatus::ok && solver_->inertia().zero > 0)
            status = LinearStatus::singular;
    }
    if (status != LinearStatus::ok)
        failure_ = "the equilibrium's Hessian H_UU could not be factorized (" + to_string(status) + ": " +
                   solver_->last_message() + "): x(θ) has no derivative there";
}

EquilibriumSensitivities::~EquilibriumSensitivities() = default;

const LinearSolverStats& EquilibriumSensitivities::linear_stats() const { return solver_->stats(); }

void EquilibriumSensitivities::require_ok() const
{
    if (!ok())
        throw std::logic_error("equilibrium sensitivities used after a failed factorization: " + failure_);
}

Eigen::MatrixXd EquilibriumSensitivities::right_hand_sides(const ParameterDirections& directions) const
{
    const int p = directions.count(num_coordinates_);
    const std::vector<int>& free = problem_.free_coordinates();
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(free.size()), p);
    if (directions.gradient_change.cols() > 0)
        for (int k = 0; k < static_cast<int>(free.size()); ++k)
            rhs.row(k) = -directions.gradient_change.row(free[k]);
    if (directions.prescribed_motion.cols() > 0)
        rhs -= free_prescribed_ * directions.prescribed_motion;  // H_UC reads prescribed rows only
    return rhs;
}

Eigen::MatrixXd EquilibriumSensitivities::derivatives(const ParameterDirections& directions)
{
    require_ok();
    const Eigen::MatrixXd rhs = right_hand_sides(directions);
    const std::vector<int>& free = problem_.free_coordinates();
    Eigen::MatrixXd dx = Eigen::MatrixXd::Zero(num_coordinates_, rhs.cols());
    if (directions.prescribed_motion.cols() > 0)
        for (const int c : problem_.prescribed_coordinates())
            dx.row(c) = directions.prescribed_motion.row(c);
    Eigen::VectorXd column;
    for (int j = 0; j < rhs.cols(); ++j) {
        const Eigen::VectorXd b = rhs.col(j);
        if (solver_->solve(b, column) != LinearStatus::ok)
            throw std::runtime_error("equilibrium sensitivities: a solve with the factorized H_UU failed: " +
                                     solver_->last_message());
        for (int k = 0; k < static_cast<int>(free.size()); ++k)
            dx(free[k], j) = column[k];
    }
    return dx;
}

Eigen::VectorXd EquilibriumSensitivities::adjoint_gradient(const Eigen::VectorXd& w,
                                                           const ParameterDirections& directions)
{
    require_ok();
    if (w.size() != num_coordinates_)
        throw InputError("equilibrium sensitivities: the adjoint weights have " + std::to_string(w.size()) +
                         " entries, expected " + std::to_string(num_coordinates_));
    const std::vector<int>& free = problem_.free_coordinates();
    Eigen::VectorXd w_U(static_cast<Eigen::Index>(free.size())), mu;
    for (int k = 0; k < static_cast<int>(free.size()); ++k)
        w_U[k] = w[free[k]];
    if (solver_->solve(w_U, mu) != LinearStatus::ok)  // H_UU μ = w_U (H_UU symmetric)
        throw std::runtime_error("equilibrium sensitivities: the adjoint solve failed: " + solver_->last_message());
    // wᵀ∂x/∂θ = w_Cᵀ m_C + w_Uᵀ H_UU⁻¹ rhs = w_Cᵀ m_C + μᵀ rhs.
    Eigen::VectorXd result = right_hand_sides(directions).transpose() * mu;
    if (directions.prescribed_motion.cols() > 0)
        for (const int c : problem_.prescribed_coordinates())
            result += w[c] * directions.prescribed_motion.row(c).transpose();
    return result;
}

} // namespace sinew
