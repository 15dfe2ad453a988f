#pragma once
// The chain rule from a pointwise model to the nodes of one linear simplex:
// F = Ds·Dm⁻¹ (seed 000 §4.1), ∂E/∂x from P (§4.4), ∂²E/∂x² from ∂P/∂F (§4.5).
#include <Eigen/Core>

namespace sinew {

/// A linear simplex with Cols + 1 nodes in Rows-dimensional space.
///
/// With Ds = [x₁ − x₀, …, x_Cols − x₀] and the rest inverse Dm⁻¹,
///     F = Ds·Dm⁻¹ = Σ_a x_a g_aᵀ,
/// where g_a (a ≥ 1) is row a − 1 of Dm⁻¹ and g₀ = −Σ_{a≥1} g_a, so
/// ∂F_ij/∂x_{a,m} = δ_im g_a[j]. For E = W ψ(F) (W the rest measure):
///     ∂E/∂x_a = W P g_a,                                   (1)
///     ∂²E/∂x_{a,m}∂x_{b,n} = W Σ_{j,l} g_a[j] ∂P_mj/∂F_nl g_b[l].   (2)
/// (1) for a ≥ 1 is W P Dm⁻ᵀ, the negative of the finite-volume forces
/// G = P·Bm with Bm = −W Dm⁻ᵀ (seed 000 §4.4), and node 0 takes minus the sum.
/// (2) is the congruence Dᵀ (∂P/∂F) D with D = ∂vec(F)/∂x, so a PSD ∂P/∂F
/// gives a PSD element Hessian (seed 000 §5.6).
///
/// Local coordinates are node-major: local index a·Rows + m.
template <int Rows, int Cols>
struct SimplexKinematics {
    static constexpr int kNodes = Cols + 1;
    static constexpr int kLocal = Rows * kNodes;
    static constexpr int kStrain = Rows * Cols;

    using Positions = Eigen::Matrix<double, Rows, kNodes>;
    using Deformation = Eigen::Matrix<double, Rows, Cols>;
    using RestInverse = Eigen::Matrix<double, Cols, Cols>;
    using ShapeGradients = Eigen::Matrix<double, Cols, kNodes>;
    using NodalVectors = Eigen::Matrix<double, Rows, kNodes>;
    using Stiffness = Eigen::Matrix<double, kStrain, kStrain>;
    using LocalHessian = Eigen::Matrix<double, kLocal, kLocal>;

    /// F = Ds·Dm⁻¹.
    static Deformation deformation_gradient(const Positions& x, const RestInverse& rest_inverse)
    {
        Deformation Ds;
        for (int a = 0; a < Cols; ++a)
            Ds.col(a) = x.col(a + 1) - x.col(0);
        return Ds * rest_inverse;
    }

    /// The columns g_a of ∂F/∂x: g_a = (Dm⁻¹)ᵀ e_{a−1} for a ≥ 1, g₀ = −Σ g_a.
    static ShapeGradients shape_gradients(const RestInverse& rest_inverse)
    {
        ShapeGradients g;
        g.template rightCols<Cols>() = rest_inverse.transpose();
        g.col(0) = -rest_inverse.transpose().rowwise().sum();
        return g;
    }

    /// ∂E/∂x_a, one column per node, by (1).
    static NodalVectors gradient(const Deformation& P, const RestInverse& rest_inverse, double measure)
    {
        NodalVectors grad;
        grad.template rightCols<Cols>() = measure * P * rest_inverse.transpose();
        grad.col(0) = -grad.template rightCols<Cols>().rowwise().sum();
        return grad;
    }

    /// The element Hessian by (2), from ∂P/∂F on vec(F) (entry
    /// (i + Rows·j, k + Rows·l) = ∂P_ij/∂F_kl). Only the lower triangle is
    /// written; the upper is left undefined.
    static void lower_hessian(const Stiffness& dPdF, const RestInverse& rest_inverse, double measure,
                              LocalHessian& H)
    {
        const ShapeGradients g = shape_gradients(rest_inverse);
        // T(r, b·Rows + n) = Σ_l ∂P_r/∂F_nl g_b[l]: the product with D on the right.
        Eigen::Matrix<double, kStrain, kLocal> T;
        for (int b = 0; b < kNodes; ++b)
            for (int n = 0; n < Rows; ++n) {
                Eigen::Matrix<double, kStrain, 1> column = dPdF.col(n) * g(0, b);
                for (int l = 1; l < Cols; ++l)
                    column += dPdF.col(n + Rows * l) * g(l, b);
                T.col(b * Rows + n) = column;
            }
        // H(a·Rows + m, ·) = W Σ_j g_a[j] T(m + Rows·j, ·): Dᵀ on the left.
        for (int q = 0; q < kLocal; ++q)
            for (int p = q; p < kLocal; ++p) {
                const int a = p / Rows;
                const int m = p % Rows;
                double sum = 0.0;
                for (int j = 0; j < Cols; ++j)
                    sum += g(j, a) * T(m + Rows * j, q);
                H(p, q) = measure * sum;
            }
    }
};

} // namespace sinew
