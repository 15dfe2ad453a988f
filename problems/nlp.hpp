#pragma once
#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace sinew {

/// Positions of the nonzeros of a sparse matrix, as (row, col) pairs, fixed at
/// setup. Values are passed separately, in the same order.
struct SparsityPattern {
    std::vector<int> rows;
    std::vector<int> cols;
    int nonzeros() const { return static_cast<int>(rows.size()); }
    void add(int row, int col)
    {
        rows.push_back(row);
        cols.push_back(col);
    }
};

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
    virtual void hessian_values(ConstVectorRef x, double sigma, ConstVectorRef lambda, VectorRef values) = 0;

    /// Whether projected_hessian_values is offered: ∇²f with every term of f
    /// (each element's ∂P/∂F, say) projected onto the PSD cone, so that the
    /// sum is PSD. Projected Newton uses it; problems without it get none.
    virtual bool has_projected_hessian() const { return false; }
    /// Values in hessian_pattern()'s order (lower triangle), σ = 1 and no
    /// constraint terms. Throws std::logic_error where not offered.
    virtual void projected_hessian_values(ConstVectorRef x, VectorRef values);

private:
    SparsityPattern empty_pattern_;
};

/// What a problem has, so that a solver can refuse what it cannot handle.
struct NlpKind {
    bool has_bounds = false;        ///< some finite x_L or x_U
    bool has_equalities = false;    ///< some g_L = g_U
    bool has_inequalities = false;  ///< some g_L < g_U
    int num_equalities = 0;
    int num_inequalities = 0;
    bool unconstrained() const { return !has_bounds && !has_equalities && !has_inequalities; }
    std::string describe() const;   ///< e.g. "bounds, 1 equality, 1 inequality"
};
NlpKind classify(const Nlp& nlp);

/// Largest violation of bounds and constraints at x (0 when feasible).
double max_constraint_violation(Nlp& nlp, Nlp::ConstVectorRef x);

} // namespace sinew
