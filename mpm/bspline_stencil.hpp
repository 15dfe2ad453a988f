#pragma once
#include <Eigen/Core>

#include <array>
#include <cmath>

namespace sinew {

/// The degree of the B-splines that weight particles on grid nodes.
enum class SplineOrder { quadratic, cubic };

/// Nodes per axis a particle's spline reaches: 3 (quadratic) or 4 (cubic).
constexpr int stencil_width(SplineOrder order) { return order == SplineOrder::quadratic ? 3 : 4; }

/// σ of APIC's D_p = Σ_i w_ip (x_i − x_p)(x_i − x_p)ᵀ = σ dx² I: 1/4 for
/// quadratic, 1/3 for cubic B-splines (Jiang et al. 2015, §5.3).
double apic_inertia_factor(SplineOrder order);

/// One particle's B-spline weights on a grid of spacing dx whose nodes sit
/// at integer multiples of dx. Along axis a the stencil's k-th node is
/// base[a] + k, at distance u = x_a/dx − (base[a] + k) cells from the
/// particle, and the 1D spline gives N(u), ∂N/∂x = N'(u)/dx and
/// ∂²N/∂x² = N''(u)/dx² (seed 004 needs N'' for the damage Laplacian). The
/// weight of a node is the product over axes, w_ip = Π_a N(u_a).
template <int Dim>
struct BSplineStencil {
    static constexpr int kMaxWidth = 4;
    using Index = Eigen::Matrix<int, Dim, 1>;
    using Vector = Eigen::Matrix<double, Dim, 1>;

    Index base;
    int width = 3;
    std::array<std::array<double, kMaxWidth>, Dim> N{}, dN{}, ddN{};

    /// w_ip at the node base + offset (0 ≤ offset[a] < width).
    double weight(const Index& offset) const
    {
        double w = 1.0;
        for (int a = 0; a < Dim; ++a)
            w *= N[a][offset[a]];
        return w;
    }

    /// ∇w_ip = (∂N/∂x_a Π_{b≠a} N)_a at the node base + offset.
    Vector gradient(const Index& offset) const
    {
        Vector g;
        for (int a = 0; a < Dim; ++a) {
            g[a] = dN[a][offset[a]];
            for (int b = 0; b < Dim; ++b)
                if (b != a)
                    g[a] *= N[b][offset[b]];
        }
        return g;
    }

    /// ΔN_i = Σ_a ∂²N/∂x_a² Π_{b≠a} N at the node base + offset: the
    /// Laplacian of w_ip in x_p (seed 004 Alg. 4, line 5).
    double laplacian(const Index& offset) const
    {
        double sum = 0.0;
        for (int a = 0; a < Dim; ++a) {
            double term = ddN[a][offset[a]];
            for (int b = 0; b < Dim; ++b)
                if (b != a)
                    term *= N[b][offset[b]];
            sum += term;
        }
        return sum;
    }

    /// Calls f(offset) for every node of the stencil, the last axis fastest.
    template <typename Function>
    void for_each_offset(Function&& f) const
    {
        Index offset = Index::Zero();
        for (;;) {
            f(static_cast<const Index&>(offset));
            int a = Dim - 1;
            while (a >= 0 && ++offset[a] == width)
                offset[a--] = 0;
            if (a < 0)
                return;
        }
    }
};

/// The first node of a stencil along one axis, x/dx = cells: ⌊cells − ½⌋
/// (quadratic) or ⌊cells⌋ − 1 (cubic), so that the particle lies within
/// the stencil's middle cell(s).
inline int first_node(double cells, SplineOrder order)
{
    return order == SplineOrder::quadratic ? static_cast<int>(std::floor(cells - 0.5))
                                           : static_cast<int>(std::floor(cells)) - 1;
}

/// The quadratic B-spline's weights N of the nodes base, base + 1, base + 2
/// along one axis (base = first_node(cells)): the branches the spline
/// takes there, u ∈ [½, 3/2), [−½, ½), [−3/2, −½).
inline void quadratic_weights(double cells, int base, double* N)
{
    const double r0 = cells - static_cast<double>(base);
    const double u1 = cells - static_cast<double>(base + 1);
    const double r2 = -(cells - static_cast<double>(base + 2));
    N[0] = 0.5 * (1.5 - r0) * (1.5 - r0);
    N[1] = 0.75 - u1 * u1;
    N[2] = 0.5 * (1.5 - r2) * (1.5 - r2);
}

/// The stencil of a particle at x on the grid of spacing dx.
template <int Dim>
BSplineStencil<Dim> bspline_stencil(const Eigen::Matrix<double, Dim, 1>& x, double dx, SplineOrder order);

/// The same stencil with the weights N only (dN, ddN left zero), as the
/// transfers need them: the same values as bspline_stencil's, bit for bit,
/// without the derivatives and the branches (quadratic B-splines).
template <int Dim>
BSplineStencil<Dim> bspline_weights(const Eigen::Matrix<double, Dim, 1>& x, double dx, SplineOrder order);

/// The stencil's first node alone: ⌊x/dx − ½⌋ (quadratic) or ⌊x/dx⌋ − 1 (cubic) per axis.
template <int Dim>
Eigen::Matrix<int, Dim, 1> stencil_base(const Eigen::Matrix<double, Dim, 1>& x, double dx, SplineOrder order);

} // namespace sinew
