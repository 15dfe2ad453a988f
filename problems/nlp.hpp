#pragma once
#include "sinew/core/near_null_space.hpp"
#include "sinew/core/projection.hpp"
#include "sinew/core/sparsity_pattern.hpp"

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace sinew {

/// A bound at or beyond this magnitude means "no bound" (Ipopt's convention).
constexpr double kInfinity = std::numeric_limits<double>::infinity();
inline bool is_finite_bound(double b) { return b > -1e19 && b < 1e19; }

/// A nonlinear program with exact first and second derivatives:
///
///     minimize f(x)  subject to  x_L <= x <= x_U,  g_L <= c(x) <= g_U
///
/// with equality constraints where g_L = g_U. Dimensions, bounds, starting
/// point and both sparsity patterns are fixed at setup; the evaluation calls
/// fill values only and must not allocate.
///
/// The Hessian is that of the Lagrangian in Ipopt's sign convention,
///     ∇²L = σ ∇²f(x) + Σᵢ λᵢ ∇²cᵢ(x),
/// lower triangle only (row >= col). Solvers using another convention convert
/// at their boundary.
///
/// An evaluation may report that f is undefined at x (an inverted element, say)
/// by returning +infinity from objective(); the other calls are then not made.
class Nlp {
public:
    using Vector = Eigen::VectorXd;
    using VectorRef = Eigen::Ref<Eigen::VectorXd>;
    using ConstVectorRef = Eigen::Ref<const Eigen::VectorXd>;

    virtual ~Nlp() = default;

    virtual std::string name() const = 0;
    virtual int num_variables() const = 0;
    virtual int num_constraints() const { return 0; }

    /// x_L, x_U; entries at ±infinity (or beyond ±1e19) are absent bounds.
    virtual void variable_bounds(VectorRef lower, VectorRef upper) const;
    /// g_L, g_U; equal entries make an equality constraint.
    virtual void constraint_bounds(VectorRef lower, VectorRef upper) const;
    virtual Vector starting_point() const = 0;

    virtual double objective(ConstVectorRef x) = 0;
    virtual void gradient(ConstVectorRef x, VectorRef grad) = 0;
    virtual void constraints(ConstVectorRef x, VectorRef c);

    /// Pattern of the constraint Jacobian ∂c/∂x (m × n).
    virtual const SparsityPattern& jacobian_pattern() const;
    virtual void jacobian_values(ConstVectorRef x, VectorRef values);

    /// Pattern of the lower triangle of ∇²L (n × n, row >= col).
    virtual const SparsityPattern& hessian_pattern() const = 0;

    /// The Hessian of the Lagrangian σ∇²f + Σᵢ λᵢ∇²cᵢ at x, lower triangle in
    /// hessian_pattern()'s order. With Projection::clamp every term (each
    /// element's ∂P/∂F, each constraint's λᵢ∇²cᵢ) is projected onto the PSD
    /// cone before the sum (seed 000 §5.6), so that σ ≥ 0 gives a PSD sum.
    /// std::logic_error for a projection the problem does not support().
    void hessian(ConstVectorRef x, double sigma, ConstVectorRef lambda, Projection projection, VectorRef values);
    /// Whether hessian() takes `projection` (every problem takes none).
    virtual bool supports(Projection projection) const { return projection == Projection::none; }
    /// False when hessian() is an approximation (Gauss-Newton, say): Ipopt
    /// then uses its limited-memory quasi-Newton mode instead.
    virtual bool exact_hessian() const { return true; }
    /// Vectors that the objective's Hessian at x nearly annihilates (the
    /// rigid-body modes of an elastic body), for an algebraic multigrid
    /// preconditioner; none unless a problem knows them.
    virtual NearNullSpace near_null_space(ConstVectorRef /*x*/) const { return {}; }

protected:
    /// hessian() with Projection::none.
    virtual void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) = 0;
    /// hessian() with Projection::clamp, for problems that support() it.
    virtual void projected_hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values);

private:
    SparsityPattern empty_pattern_;
};

/// What a problem has and offers, so that a solver can refuse what it cannot
/// handle: every solver's refusal reads this one type.
struct NlpCapabilities {
    bool has_bounds = false;        ///< some finite x_L or x_U
    bool has_equalities = false;    ///< some g_L = g_U
    bool has_inequalities = false;  ///< some g_L < g_U
    int num_equalities = 0;
    int num_inequalities = 0;
    bool exact_hessian = true;           ///< Nlp::exact_hessian()
    bool projected_hessian = false;      ///< Nlp::supports(Projection::clamp)
    bool unconstrained() const { return !has_bounds && !has_equalities && !has_inequalities; }
    std::string describe() const;   ///< e.g. "bounds, 1 equality, 1 inequality"
};
NlpCapabilities capabilities_of(const Nlp& nlp);

/// Largest violation of bounds and constraints at x (0 when feasible).
double max_constraint_violation(Nlp& nlp, Nlp::ConstVectorRef x);

} // namespace sinew
