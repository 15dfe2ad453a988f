#pragma once
#include "sinew/problems/nlp.hpp"

#include <vector>

namespace sinew {

/// Simple bounds x_L ≤ x ≤ x_U in the Newton solvers, by projection and an
/// ε-active set (Bertsekas, "Projected Newton methods for optimization
/// problems with simple constraints", SIAM J. Control Optim. 20, 1982): a
/// variable at (within ε of) a bound that the gradient g pushes outward is
/// held there (its Newton row becomes the identity, its step zero); the other
/// variables take the Newton step, and every trial point is projected back
/// into the box. Problems without bounds skip all of it.
class ActiveBounds {
public:
    explicit ActiveBounds(const Nlp& nlp);

    bool any() const { return any_; }
    /// x ← P(x), the nearest point of the box.
    void project(Eigen::VectorXd& x) const;
    /// The ε-active set for x and the gradient (of the Lagrangian) g, with
    /// ε = min(1e-3, ‖x − P(x − g)‖∞); fixed()[i] != 0 marks variable i.
    void update(const Eigen::VectorXd& x, const Eigen::VectorXd& g);
    const std::vector<char>& fixed() const { return fixed_; }
    /// ‖x − P(x − g)‖∞: zero exactly at a stationary point of the box-constrained problem.
    double projected_gradient_norm(const Eigen::VectorXd& x, const Eigen::VectorXd& g) const;
    /// z_L, z_U ≥ 0 from g where a bound is active at x (g = z_L − z_U there), zero elsewhere.
    void multipliers(const Eigen::VectorXd& x, const Eigen::VectorXd& g, Eigen::VectorXd& z_lower,
                     Eigen::VectorXd& z_upper) const;

private:
    Eigen::VectorXd lower_, upper_;
    bool any_ = false;
    std::vector<char> fixed_;
};

} // namespace sinew
