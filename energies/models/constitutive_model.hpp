#pragma once
#include "sinew/core/projection.hpp"
#include <Eigen/Core>

#include <limits>
#include <string>

namespace sinew {

/// Per-element data a model reads, passed explicitly with every call.
template <int MaterialDim>
struct MaterialPoint {
    /// Fiber direction a₀ in material (rest) space, unit length.
    Eigen::Matrix<double, MaterialDim, 1> fiber = Eigen::Matrix<double, MaterialDim, 1>::UnitX();
    double activation = 0.0;  ///< muscle activation α ∈ [0, 1]
    double damage = 0.0;      ///< damage d ∈ [0, 1]
};

/// A hyperelastic model as a pointwise function of the deformation gradient
/// F (Rows × Cols = space dim × material dim: 3×3 tets, 2×2 plane triangles,
/// 3×2 triangles in 3D). Virtual only here, at the small fixed-size stencil.
///
/// ∂P/∂F is a (Rows·Cols)² matrix on vec(F) in Eigen's column-major order:
/// entry (i + Rows·j, k + Rows·l) = ∂P_ij/∂F_kl.
template <int Rows, int Cols>
class ConstitutiveModel {
public:
    static constexpr int kRows = Rows;
    static constexpr int kCols = Cols;
    static constexpr int kSize = Rows * Cols;
    using Deformation = Eigen::Matrix<double, Rows, Cols>;
    using Stress = Eigen::Matrix<double, Rows, Cols>;
    using Stiffness = Eigen::Matrix<double, kSize, kSize>;
    using Point = MaterialPoint<Cols>;

    virtual ~ConstitutiveModel() = default;
    virtual std::string name() const = 0;

    /// ψ(F), energy per unit rest measure (J/m³, or J/m² for membranes).
    /// +infinity where the model is undefined (never NaN).
    virtual double energy(const Deformation& F, const Point& point) const = 0;

    /// ψ(F) returned; P = ∂ψ/∂F written when `P` is not null; ∂P/∂F (projected
    /// as asked) written when `dPdF` is not null. One call so that the
    /// decompositions are shared.
    virtual double evaluate(const Deformation& F, const Point& point, Stress* P, Stiffness* dPdF,
                            Projection projection) const = 0;

    /// ∂ψ/∂α returned and ∂P/∂α written into `dP_dalpha` (when not null): the
    /// derivatives in the activation α of the material point, at `point`'s own
    /// α. A model whose ψ does not depend on α (the default) gives zeros; the
    /// muscle model, linear in α (seed 000 eq. 4), gives its active part.
    /// +infinity (and a zero ∂P/∂α) where ψ is undefined, as energy().
    virtual double activation_derivative(const Deformation& F, const Point& point, Stress* dP_dalpha) const
    {
        if (dP_dalpha)
            dP_dalpha->setZero();
        return energy(F, point) < std::numeric_limits<double>::infinity() ? 0.0
                                                                           : std::numeric_limits<double>::infinity();
    }

    /// evaluate for k < count: ψ(F[k]) into psi[k], and P, ∂P/∂F into P[k],
    /// dPdF[k] when those arrays are not null. The default calls evaluate for
    /// each; the 3×3 models that need the SVD of F evaluate several elements
    /// side by side in SIMD lanes (isotropic_batch.hpp, the QR and muscle
    /// models).
    virtual void evaluate_batch(int count, const Deformation* F, const Point* points, double* psi, Stress* P,
                                Stiffness* dPdF, Projection projection) const
    {
        for (int k = 0; k < count; ++k)
            psi[k] = evaluate(F[k], points[k], P ? P + k : nullptr, dPdF ? dPdF + k : nullptr, projection);
    }
};

using Model3d = ConstitutiveModel<3, 3>;
using Model2d = ConstitutiveModel<2, 2>;
using MembraneModel = ConstitutiveModel<3, 2>;

} // namespace sinew
