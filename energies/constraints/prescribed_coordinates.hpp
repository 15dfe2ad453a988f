#pragma once
#include "sinew/energies/constraints/constraint_set.hpp"

#include <vector>

namespace sinew {

/// Dirichlet conditions as equalities: c_k(x) = x_{i_k} − x̄_k, one per
/// prescribed coordinate i_k (a unit row of the Jacobian, no curvature).
class PrescribedCoordinates final : public ConstraintSet {
public:
    /// `coordinates` are indices into x (each once); `targets` their values x̄.
    PrescribedCoordinates(std::vector<int> coordinates, Eigen::VectorXd targets);

    /// New x̄ (a moved cranium, a load step); the patterns do not change.
    void set_targets(const Eigen::VectorXd& targets) { targets_ = targets; }
    const std::vector<int>& coordinates() const { return coordinates_; }

    std::string name() const override { return "prescribed coordinates"; }
    int num_constraints() const override { return static_cast<int>(coordinates_.size()); }
    void values(ConstVectorRef x, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_; }
    void jacobian_values(ConstVectorRef, VectorRef values) override { values.setOnes(); }
    const SparsityPattern& hessian_pattern() const override { return no_curvature_; }
    void hessian_values(ConstVectorRef, ConstVectorRef, Projection, VectorRef) override {}

private:
    std::vector<int> coordinates_;
    Eigen::VectorXd targets_;
    SparsityPattern jacobian_, no_curvature_;
};

} // namespace sinew
