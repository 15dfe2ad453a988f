#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/model_parameters.hpp"

#include <string>
#include <vector>

namespace sinew {

/// Stable Neo-Hookean (Smith, de Goes, Kim 2018, "Stable Neo-Hookean Flesh
/// Simulation"), in the form without the log(I_C + 1) term:
///
///     ψ = μ/2 (I_C − 3) − μ (J − 1) + λ'/2 (J − 1)²,   I_C = ‖F‖², J = det F,
///
/// with λ' = λ + μ, so that the linearization at F = I is linear elasticity
/// with the Lamé parameters μ, λ the user gives. P(I) = 0, ψ(I) = 0, ψ ≥ 0.
/// A polynomial in F: defined, finite and smooth for inverted F.
/// Docs: docs/energies.md (stable-neo-hookean).
class StableNeoHookean final : public Model3d {
public:
    static constexpr const char* kName = "stable-neo-hookean";

    /// mu (Pa, > 0) and lambda (Pa, >= 0): the Lamé parameters of the linearization.
    static std::vector<ParameterSpec> parameter_specs();

    /// From values already checked by resolve_parameters against parameter_specs().
    explicit StableNeoHookean(const ParameterValues& parameters);

    std::string name() const override { return kName; }
    double energy(const Deformation& F, const Point& point) const override;
    /// ∂P/∂F analytic in F; Projection::clamp clamps the 9 eigenvalues of the
    /// paper's analytic eigensystem and assembles ∂P/∂F from it (needs one SVD,
    /// skipped by Projection::none).
    double evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                    Projection projection) const override;
    /// With Projection::clamp and ∂P/∂F, everything in SIMD lanes (isotropic_batch.hpp).
    void evaluate_batch(int count, const Deformation* F, const Point* points, double* psi, Stress* P,
                        Stiffness* dPdF, Projection projection) const override;

private:
    /// ψ, P and the exact ∂P/∂F from F alone (no SVD).
    double evaluate_exact(const Deformation& F, Stress* P, Stiffness* dPdF) const;

    double mu_;             ///< μ, Pa
    double lambda_stable_;  ///< λ' = λ + μ, Pa: the energy's own coefficient
};

} // namespace sinew
