#pragma once
#include "sinew/problems/nlp.hpp"

#include <vector>

namespace sinew {

/// An NLP with inequalities rewritten as equalities on slack variables
/// (Wächter & Biegler 2006, §3.4): w = (x, s), one slack per inequality row,
///
///     minimize f(x)  subject to  r(w) = 0,  w_L ≤ w ≤ w_U,
///     r_E(w) = c_E(x) − g_E            (equality rows),
///     r_I(w) = c_I(x) − s,  g_L ≤ s ≤ g_U  (inequality rows).
///
/// Every constraint of the result is an equality with right-hand side 0 and
/// every one-sided physics is a bound, which is all an interior-point method
/// needs. The Lagrangian's Hessian is the problem's: the slacks enter linearly.
/// Multipliers carry over unchanged: stationarity in s gives λ_I = z_U,s − z_L,s,
/// Ipopt's sign convention for the original rows.
class SlackFormulation final : public Nlp {
public:
    explicit SlackFormulation(Nlp& problem);

    int num_slacks() const { return static_cast<int>(slack_rows_.size()); }
    /// The original problem's variables: x = w.head(n).
    int num_original_variables() const { return n_; }
    /// w = (x, c_I(x)) at the problem's starting point.
    Vector starting_point() const override;

    std::string name() const override { return problem_.name(); }
    int num_variables() const override { return n_ + num_slacks(); }
    int num_constraints() const override { return m_; }
    void variable_bounds(VectorRef lower, VectorRef upper) const override;
    void constraint_bounds(VectorRef lower, VectorRef upper) const override;
    double objective(ConstVectorRef w) override { return problem_.objective(w.head(n_)); }
    void gradient(ConstVectorRef w, VectorRef grad) override;
    /// r(w).
    void constraints(ConstVectorRef w, VectorRef r) override;
    /// The problem's Jacobian pattern, then one −1 per slack (row i, column n + k).
    const SparsityPattern& jacobian_pattern() const override { return jacobian_pattern_; }
    void jacobian_values(ConstVectorRef w, VectorRef values) override;
    const SparsityPattern& hessian_pattern() const override { return problem_.hessian_pattern(); }
    bool supports(Projection projection) const override { return problem_.supports(projection); }
    bool exact_hessian() const override { return problem_.exact_hessian(); }

protected:
    void hessian_values(ConstVectorRef w, double sigma, ConstVectorRef lambda, VectorRef values) override;
    void projected_hessian_values(ConstVectorRef w, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    Nlp& problem_;
    int n_, m_;
    Eigen::VectorXd row_lower_, row_upper_;  ///< g_L, g_U
    std::vector<int> slack_rows_;           ///< the row of each slack
    SparsityPattern jacobian_pattern_;
    int problem_jacobian_nonzeros_;
};

} // namespace sinew
