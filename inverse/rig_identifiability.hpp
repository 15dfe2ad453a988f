#pragma once
// Whether the landmarks determine the rig's parameters: the local rank of
// the fit's Gauss-Newton model with the orthogonality constraints.
#include "sinew/inverse/rig_fit_problem.hpp"

#include <string>
#include <vector>

namespace sinew {

struct RigIdentifiability {
    int parameters = 0;
    int rank = 0;
    double singular_value_ratio = 0.0;  ///< σ_min / σ_max of the column-scaled stack (0 with fewer rows than parameters)
    /// For each direction the stack does not see, the parameter moving most
    /// along it (rig_parameter_name).
    std::vector<std::string> undetermined;
    bool determined() const { return rank == parameters; }
    /// "34 parameters, rank 34 (σ_min/σ_max = 3.1e-04)" or "… rank 18: the
    /// landmarks do not determine 8 directions (moving most: M_j(0,1), …); …".
    std::string message;
};

/// Relative singular value below which a direction counts as undetermined.
inline constexpr double kIdentifiabilityTolerance = 1e-8;

/// The rank at θ of A = [J; √τ E_α; ∂c/∂θ] (J the landmarks' Jacobian, E_α
/// picking the activations when the fit has a Tikhonov term τ > 0, c the 12
/// orthogonality conditions, in either form): the parameters are locally
/// determined by the landmarks exactly when A has full column rank (the
/// reduced Gauss-Newton Hessian Zᵀ(JᵀJ + τE_αᵀE_α)Z on the constraints'
/// tangent space is then positive definite). Columns are scaled to unit norm
/// first, so units (activations, map entries, metres) do not count; σ_i is
/// zero when σ_i ≤ kIdentifiabilityTolerance σ_max. std::runtime_error
/// where the inner solve fails at θ.
RigIdentifiability rig_identifiability(RigFitProblem& problem, const Eigen::VectorXd& theta);

} // namespace sinew
