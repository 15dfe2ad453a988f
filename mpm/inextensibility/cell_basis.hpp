#pragma once
// The multipliers' basis of the grid inextensibility (seed 004 §4): one
// multiplier per grid cell, at its centre, with the linear (tent) B-spline.
#include <Eigen/Core>

#include <cmath>

namespace sinew {

/// Γ_c(x) for the 2^Dim cells around x: cell k has its centre at (k + ½) dx
/// and Γ_c(x) = Π_d N₁((x_d − (k_d + ½) dx)/dx), N₁ the tent of width 2.
/// The weights are ≥ 0, sum to 1 and reproduce linear fields (Σ_c Γ_c x_c = x).
template <int Dim>
struct CellStencil {
    using Index = Eigen::Matrix<int, Dim, 1>;
    Index base;                          ///< the lowest of the 2^Dim cells
    Eigen::Matrix<double, Dim, 2> axis;  ///< per axis, the weight of cell base_d and of base_d + 1

    /// f(cell, Γ_c(x)) for each of the 2^Dim cells, last axis fastest.
    template <typename Visit>
    void for_each(Visit&& f) const
    {
        for (int corner = 0; corner < (1 << Dim); ++corner) {
            Index cell = base;
            double weight = 1.0;
            for (int d = 0; d < Dim; ++d) {
                const int bit = (corner >> (Dim - 1 - d)) & 1;
                cell[d] += bit;
                weight *= axis(d, bit);
            }
            f(cell, weight);
        }
    }
};

template <int Dim>
CellStencil<Dim> cell_stencil(const Eigen::Matrix<double, Dim, 1>& x, double dx)
{
    CellStencil<Dim> stencil;
    for (int d = 0; d < Dim; ++d) {
        const double s = x[d] / dx - 0.5;  // in units of dx, from the centre of cell 0
        const double lower = std::floor(s);
        const double t = s - lower;
        stencil.base[d] = static_cast<int>(lower);
        stencil.axis(d, 0) = 1.0 - t;
        stencil.axis(d, 1) = t;
    }
    return stencil;
}

} // namespace sinew
