#include "sinew/mpm/bspline_stencil.hpp"

#include <cmath>

namespace sinew {
namespace {

/// N(u), N'(u), N''(u) of the 1D B-spline, u in cells from the node.
struct SplineValues {
    double N = 0.0, dN = 0.0, ddN = 0.0;
};

// Quadratic: N = 3/4 − u² for |u| < 1/2, ½(3/2 − |u|)² for 1/2 ≤ |u| < 3/2.
SplineValues quadratic(double u)
{
    const double r = std::abs(u), sign = u < 0.0 ? -1.0 : 1.0;
    if (r < 0.5)
        return {0.75 - u * u, -2.0 * u, -2.0};
    if (r < 1.5)
        return {0.5 * (1.5 - r) * (1.5 - r), -sign * (1.5 - r), 1.0};
    return {};
}

// Cubic: N = ½|u|³ − u² + 2/3 for |u| < 1, (2 − |u|)³/6 for 1 ≤ |u| < 2.
SplineValues cubic(double u)
{
    const double r = std::abs(u), sign = u < 0.0 ? -1.0 : 1.0;
    if (r < 1.0)
        return {0.5 * r * r * r - r * r + 2.0 / 3.0, 1.5 * u * r - 2.0 * u, 3.0 * r - 2.0};
    if (r < 2.0)
        return {(2.0 - r) * (2.0 - r) * (2.0 - r) / 6.0, -sign * 0.5 * (2.0 - r) * (2.0 - r), 2.0 - r};
    return {};
}

} // namespace

double apic_inertia_factor(SplineOrder order) { return order == SplineOrder::quadratic ? 0.25 : 1.0 / 3.0; }

template <int Dim>
Eigen::Matrix<int, Dim, 1> stencil_base(const Eigen::Matrix<double, Dim, 1>& x, double dx, SplineOrder order)
{
    Eigen::Matrix<int, Dim, 1> base;
    for (int a = 0; a < Dim; ++a)
        base[a] = first_node(x[a] / dx, order);
    return base;
}

template <int Dim>
BSplineStencil<Dim> bspline_weights(const Eigen::Matrix<double, Dim, 1>& x, double dx, SplineOrder order)
{
    if (order != SplineOrder::quadratic)
        return bspline_stencil<Dim>(x, dx, order);
    BSplineStencil<Dim> stencil;
    stencil.width = 3;
    for (int a = 0; a < Dim; ++a) {
        const double cells = x[a] / dx;
        stencil.base[a] = first_node(cells, order);
        quadratic_weights(cells, stencil.base[a], stencil.N[a].data());
    }
    return stencil;
}

template <int Dim>
BSplineStencil<Dim> bspline_stencil(const Eigen::Matrix<double, Dim, 1>& x, double dx, SplineOrder order)
{
    BSplineStencil<Dim> stencil;
    stencil.width = stencil_width(order);
    for (int a = 0; a < Dim; ++a) {
        const double cells = x[a] / dx;
        const int base = first_node(cells, order);
        stencil.base[a] = base;
        for (int k = 0; k < stencil.width; ++k) {
            const double u = cells - static_cast<double>(base + k);
            const SplineValues s = order == SplineOrder::quadratic ? quadratic(u) : cubic(u);
            stencil.N[a][k] = s.N;
            stencil.dN[a][k] = s.dN / dx;
            stencil.ddN[a][k] = s.ddN / (dx * dx);
        }
    }
    return stencil;
}

template BSplineStencil<2> bspline_stencil<2>(const Eigen::Matrix<double, 2, 1>&, double, SplineOrder);
template BSplineStencil<3> bspline_stencil<3>(const Eigen::Matrix<double, 3, 1>&, double, SplineOrder);
template BSplineStencil<2> bspline_weights<2>(const Eigen::Matrix<double, 2, 1>&, double, SplineOrder);
template BSplineStencil<3> bspline_weights<3>(const Eigen::Matrix<double, 3, 1>&, double, SplineOrder);
template Eigen::Matrix<int, 2, 1> stencil_base<2>(const Eigen::Matrix<double, 2, 1>&, double, SplineOrder);
template Eigen::Matrix<int, 3, 1> stencil_base<3>(const Eigen::Matrix<double, 3, 1>&, double, SplineOrder);

} // namespace sinew
