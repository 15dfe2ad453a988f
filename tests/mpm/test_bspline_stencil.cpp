// B-spline stencils of MPM (issue 33): partition of unity, the moments APIC
// relies on, and the derivatives against central differences.
#include "sinew/mpm/bspline_stencil.hpp"

#include <catch2/catch.hpp>

#include <random>

using namespace sinew;

namespace {

template <int Dim>
Eigen::Matrix<double, Dim, 1> random_point(std::mt19937& rng, double lower, double upper)
{
    std::uniform_real_distribution<double> u(lower, upper);
    Eigen::Matrix<double, Dim, 1> x;
    for (int a = 0; a < Dim; ++a)
        x[a] = u(rng);
    return x;
}

/// Σ w = 1, Σ w (x_i − x_p) = 0, Σ w (x_i − x_p)(x_i − x_p)ᵀ = σ dx² I and Σ ∇w = 0.
template <int Dim>
void check_moments(SplineOrder order)
{
    std::mt19937 rng(7);
    const double dx = 0.37;
    using Index = Eigen::Matrix<int, Dim, 1>;
    using Vector = Eigen::Matrix<double, Dim, 1>;
    using Matrix = Eigen::Matrix<double, Dim, Dim>;
    for (int trial = 0; trial < 200; ++trial) {
        const Vector x = random_point<Dim>(rng, -5.0, 5.0);
        const BSplineStencil<Dim> stencil = bspline_stencil<Dim>(x, dx, order);
        double sum = 0.0;
        Vector first = Vector::Zero(), gradient_sum = Vector::Zero();
        Matrix second = Matrix::Zero();
        stencil.for_each_offset([&](const Index& offset) {
            const double w = stencil.weight(offset);
            const Vector d = (stencil.base + offset).template cast<double>() * dx - x;
            CHECK(w >= 0.0);
            sum += w;
            first += w * d;
            second += w * d * d.transpose();
            gradient_sum += stencil.gradient(offset);
        });
        CAPTURE(trial, x.transpose());
        CHECK(sum == Approx(1.0).margin(1e-14));
        CHECK(first.cwiseAbs().maxCoeff() < 1e-14);
        CHECK((second - apic_inertia_factor(order) * dx * dx * Matrix::Identity()).cwiseAbs().maxCoeff() < 1e-14);
        CHECK(gradient_sum.cwiseAbs().maxCoeff() < 1e-12);
    }
}

/// The 1D spline of axis 0 at node offset k as a function of x[0].
double spline_value(const Eigen::Vector2d& x, double dx, SplineOrder order, int node)
{
    const BSplineStencil<2> s = bspline_stencil<2>(x, dx, order);
    const int k = node - s.base[0];
    return k >= 0 && k < s.width ? s.N[0][k] : 0.0;
}

double spline_slope(const Eigen::Vector2d& x, double dx, SplineOrder order, int node)
{
    const BSplineStencil<2> s = bspline_stencil<2>(x, dx, order);
    const int k = node - s.base[0];
    return k >= 0 && k < s.width ? s.dN[0][k] : 0.0;
}

} // namespace

TEST_CASE("B-spline stencils: partition of unity and APIC's moments, quadratic and cubic, 2D and 3D")
{
    check_moments<2>(SplineOrder::quadratic);
    check_moments<3>(SplineOrder::quadratic);
    check_moments<2>(SplineOrder::cubic);
    check_moments<3>(SplineOrder::cubic);
}

TEST_CASE("B-spline stencils: N' and N'' against central differences of N and N'")
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    const double dx = 0.5, h = 1e-6;
    for (SplineOrder order : {SplineOrder::quadratic, SplineOrder::cubic}) {
        for (int trial = 0; trial < 300; ++trial) {
            const Eigen::Vector2d x(u(rng), 0.0);
            const BSplineStencil<2> s = bspline_stencil<2>(x, dx, order);
            for (int k = 0; k < s.width; ++k) {
                const int node = s.base[0] + k;
                const double fraction = x[0] / dx - node;  // u in cells: skip the breakpoints of N''
                if (std::abs(std::abs(fraction) - std::round(2.0 * std::abs(fraction)) / 2.0) < 1e-4)
                    continue;
                const Eigen::Vector2d step(h, 0.0);
                const double slope =
                    (spline_value(x + step, dx, order, node) - spline_value(x - step, dx, order, node)) / (2.0 * h);
                const double curvature =
                    (spline_slope(x + step, dx, order, node) - spline_slope(x - step, dx, order, node)) / (2.0 * h);
                CAPTURE(trial, x[0], k);
                CHECK(s.dN[0][k] == Approx(slope).margin(1e-7));
                CHECK(s.ddN[0][k] == Approx(curvature).margin(1e-5));
            }
        }
    }
}

TEST_CASE("B-spline stencils: the gradient is the product rule of the axes' splines")
{
    const Eigen::Vector3d x(0.31, -1.27, 2.05);
    const double dx = 0.2, h = 1e-7;
    const BSplineStencil<3> s = bspline_stencil<3>(x, dx, SplineOrder::cubic);
    s.for_each_offset([&](const Eigen::Vector3i& offset) {
        const Eigen::Vector3i node = s.base + offset;
        for (int a = 0; a < 3; ++a) {
            Eigen::Vector3d step = Eigen::Vector3d::Zero();
            step[a] = h;
            auto weight_at = [&](const Eigen::Vector3d& y) {
                const BSplineStencil<3> t = bspline_stencil<3>(y, dx, SplineOrder::cubic);
                return t.weight(node - t.base);
            };
            const double difference = (weight_at(x + step) - weight_at(x - step)) / (2.0 * h);
            CHECK(s.gradient(offset)[a] == Approx(difference).margin(1e-6));
        }
    });
}

TEST_CASE("B-spline stencil: the transfers' weights-only stencil gives the same weights bit for bit")
{
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> position(-3.0, 3.0);
    for (const SplineOrder order : {SplineOrder::quadratic, SplineOrder::cubic})
        for (int sample = 0; sample < 1000; ++sample) {
            const Eigen::Vector3d x(position(rng), position(rng), position(rng));
            const BSplineStencil<3> full = bspline_stencil<3>(x, 0.07, order);
            const BSplineStencil<3> weights = bspline_weights<3>(x, 0.07, order);
            CHECK(weights.base == full.base);
            CHECK(stencil_base<3>(x, 0.07, order) == full.base);
            CHECK(weights.width == full.width);
            CHECK(weights.N == full.N);
        }
}

namespace {

/// Σ_i ΔN_i = 0, Σ_i ΔN_i (x_i − x_p) = 0 and Σ_i ΔN_i |x_i − x_p|² = 2·Dim:
/// the splines reproduce quadratics up to a constant (the moments above),
/// so the Laplacian of Σ_i N_i(x)|x_i − y|² = |x − y|² + σ dx² Dim is 2·Dim.
template <int Dim>
void check_laplacian_moments(SplineOrder order)
{
    std::mt19937 rng(13);
    const double dx = 0.29;
    using Index = Eigen::Matrix<int, Dim, 1>;
    using Vector = Eigen::Matrix<double, Dim, 1>;
    for (int trial = 0; trial < 200; ++trial) {
        const Vector x = random_point<Dim>(rng, -4.0, 4.0);
        const BSplineStencil<Dim> stencil = bspline_stencil<Dim>(x, dx, order);
        double sum = 0.0, second = 0.0;
        Vector first = Vector::Zero();
        stencil.for_each_offset([&](const Index& offset) {
            const double laplacian = stencil.laplacian(offset);
            const Vector d = (stencil.base + offset).template cast<double>() * dx - x;
            sum += laplacian;
            first += laplacian * d;
            second += laplacian * d.squaredNorm();
        });
        CAPTURE(trial, x.transpose());
        CHECK(std::abs(sum) < 1e-10 / (dx * dx));
        CHECK(first.cwiseAbs().maxCoeff() < 1e-10 / dx);
        CHECK(second == Approx(2.0 * Dim).epsilon(1e-11));
    }
}

} // namespace

TEST_CASE("B-spline stencils: the Laplacian of the weights annihilates constants and lines and gives 2 Dim on squares",
          "[mpm][damage]")
{
    check_laplacian_moments<2>(SplineOrder::quadratic);
    check_laplacian_moments<3>(SplineOrder::quadratic);
    check_laplacian_moments<2>(SplineOrder::cubic);
    check_laplacian_moments<3>(SplineOrder::cubic);
}

TEST_CASE("B-spline stencils: the Laplacian is the trace of the weights' Hessian by central differences of the gradient",
          "[mpm][damage]")
{
    const Eigen::Vector3d x(0.31, -1.27, 2.05);
    const double dx = 0.2, h = 1e-6;
    const BSplineStencil<3> s = bspline_stencil<3>(x, dx, SplineOrder::cubic);
    s.for_each_offset([&](const Eigen::Vector3i& offset) {
        const Eigen::Vector3i node = s.base + offset;
        double trace = 0.0;
        for (int a = 0; a < 3; ++a) {
            Eigen::Vector3d step = Eigen::Vector3d::Zero();
            step[a] = h;
            auto gradient_at = [&](const Eigen::Vector3d& y) {
                const BSplineStencil<3> t = bspline_stencil<3>(y, dx, SplineOrder::cubic);
                return t.gradient(node - t.base)[a];
            };
            trace += (gradient_at(x + step) - gradient_at(x - step)) / (2.0 * h);
        }
        CHECK(s.laplacian(offset) == Approx(trace).margin(1e-4));
    });
}
