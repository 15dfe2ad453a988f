#pragma once
// Finite-difference and spectral checks of a total potential, shared by the
// potential and quasistatic tests.
#include "sinew/energies/potentials/total_potential.hpp"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>

namespace sinew::test {

/// The symmetric matrix whose lower triangle `values` holds in `pattern`'s order.
inline Eigen::MatrixXd dense_symmetric(const HessianPattern& pattern, const Eigen::VectorXd& values)
{
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(pattern.num_coordinates(), pattern.num_coordinates());
    for (int k = 0; k < pattern.nonzeros(); ++k) {
        H(pattern.rows()[k], pattern.cols()[k]) += values[k];
        if (pattern.rows()[k] != pattern.cols()[k])
            H(pattern.cols()[k], pattern.rows()[k]) += values[k];
    }
    return H;
}

inline Eigen::MatrixXd dense_hessian(TotalPotential& E, const Eigen::VectorXd& x, Projection projection)
{
    Eigen::VectorXd values(E.hessian_pattern().nonzeros());
    E.hessian_values(x, projection, values);
    return dense_symmetric(E.hessian_pattern(), values);
}

inline Eigen::VectorXd gradient_of(TotalPotential& E, const Eigen::VectorXd& x)
{
    Eigen::VectorXd g(x.size());
    E.gradient(x, g);
    return g;
}

/// ∇E by central differences of E with step h.
inline Eigen::VectorXd finite_difference_gradient(TotalPotential& E, const Eigen::VectorXd& x, double h)
{
    Eigen::VectorXd g(x.size());
    for (int i = 0; i < x.size(); ++i) {
        Eigen::VectorXd xp = x, xm = x;
        xp[i] += h;
        xm[i] -= h;
        g[i] = (E.value(xp) - E.value(xm)) / (2 * h);
    }
    return g;
}

/// ∇²E by central differences of ∇E with step h (column i from coordinate i).
inline Eigen::MatrixXd finite_difference_hessian(TotalPotential& E, const Eigen::VectorXd& x, double h)
{
    Eigen::MatrixXd H(x.size(), x.size());
    for (int i = 0; i < x.size(); ++i) {
        Eigen::VectorXd xp = x, xm = x;
        xp[i] += h;
        xm[i] -= h;
        H.col(i) = (gradient_of(E, xp) - gradient_of(E, xm)) / (2 * h);
    }
    return H;
}

/// |a − b|∞ / |b|∞ (b the reference, nonzero).
template <typename A, typename B>
double relative_error(const A& a, const B& b)
{
    return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

/// Worst relative errors of the analytic gradient against central differences
/// of E, and of the analytic Hessian against central differences of ∇E, with
/// the sizes of the references (to check they are not zero).
struct DerivativeErrors {
    double gradient = 0.0;
    double hessian = 0.0;
    double gradient_scale = 0.0;
    double hessian_scale = 0.0;
};

inline DerivativeErrors derivative_errors(TotalPotential& E, const Eigen::VectorXd& x, double h = 1e-6)
{
    DerivativeErrors errors;
    const Eigen::VectorXd g = gradient_of(E, x);
    const Eigen::VectorXd g_fd = finite_difference_gradient(E, x, h);
    errors.gradient_scale = g_fd.cwiseAbs().maxCoeff();
    errors.gradient = relative_error(g, g_fd);
    const Eigen::MatrixXd H = dense_hessian(E, x, Projection::none);
    const Eigen::MatrixXd H_fd = finite_difference_hessian(E, x, h);
    errors.hessian_scale = H_fd.cwiseAbs().maxCoeff();
    errors.hessian = relative_error(H, H_fd);
    return errors;
}

inline double smallest_eigenvalue(const Eigen::MatrixXd& H)
{
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H, Eigen::EigenvaluesOnly).eigenvalues()[0];
}

} // namespace sinew::test
