#pragma once
#include "sinew/problems/nlp.hpp"

#include <optional>
#include <string>

namespace sinew {

/// The constraints of an NLP whose constraints are all equalities
/// g_L = c(x) = g_U, as residuals c̃(x) = c(x) − g_L, with the Jacobian's
/// values and products. Evaluation does not allocate.
class EqualityConstraints {
public:
    explicit EqualityConstraints(Nlp& nlp);

    int size() const { return static_cast<int>(target_.size()); }
    const SparsityPattern& pattern() const { return nlp_.jacobian_pattern(); }
    /// c̃(x) = c(x) − g_L.
    void residuals(const Eigen::VectorXd& x, Eigen::VectorXd& c);
    /// J's values in pattern order.
    void jacobian(const Eigen::VectorXd& x, Eigen::VectorXd& values);
    /// out = Jᵀ v for J given by its pattern values.
    void transpose_times(const Eigen::VectorXd& values, const Eigen::VectorXd& v, Eigen::VectorXd& out) const;

private:
    Nlp& nlp_;
    Eigen::VectorXd target_;  ///< g_L
};

/// Why a strategy for equality constraints and bounds cannot take `nlp`
/// (inequality constraints: naming Ipopt; neither constraints nor bounds:
/// naming projected Newton, the same Newton without the strategy); nothing
/// when it can.
std::optional<std::string> refuse_inequalities(const std::string& solver, const Nlp& nlp);

} // namespace sinew
