#include "sinew/solvers/interior/barrier_bounds.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

/// κ_Σ of Wächter & Biegler 2006, eq. 16.
constexpr double kSigmaSafeguard = 1e10;

} // namespace

BarrierBounds::BarrierBounds(const Nlp& nlp, double relax)
{
    const int n = nlp.num_variables();
    original_lower_.resize(n);
    original_upper_.resize(n);
    nlp.variable_bounds(original_lower_, original_upper_);
    lower_ = original_lower_;
    upper_ = original_upper_;
    has_lower_ = Vector::Zero(n);
    has_upper_ = Vector::Zero(n);
    for (int i = 0; i < n; ++i) {
        if (is_finite_bound(lower_[i])) {
            has_lower_[i] = 1.0;
            lower_[i] -= relax * std::max(1.0, std::abs(lower_[i]));
        }
        if (is_finite_bound(upper_[i])) {
            has_upper_[i] = 1.0;
            upper_[i] += relax * std::max(1.0, std::abs(upper_[i]));
        }
    }
}

void BarrierBounds::push_inside(Vector& w, double push, double fraction) const
{
    for (int i = 0; i < size(); ++i) {
        const double width = has_lower(i) && has_upper(i) ? upper_[i] - lower_[i] : kInfinity;
        if (has_lower(i)) {
            const double p = std::min(push * std::max(1.0, std::abs(lower_[i])), fraction * width);
            w[i] = std::max(w[i], lower_[i] + p);
        }
        if (has_upper(i)) {
            const double p = std::min(push * std::max(1.0, std::abs(upper_[i])), fraction * width);
            w[i] = std::min(w[i], upper_[i] - p);
        }
    }
}

void BarrierBounds::distances(const Vector& w, Vector& to_lower, Vector& to_upper) const
{
    to_lower.resize(size());
    to_upper.resize(size());
    for (int i = 0; i < size(); ++i) {
        to_lower[i] = has_lower(i) ? w[i] - lower_[i] : 1.0;
        to_upper[i] = has_upper(i) ? upper_[i] - w[i] : 1.0;
    }
}

double BarrierBounds::barrier(const Vector& w, double mu) const
{
    double sum = 0.0;
    for (int i = 0; i < size(); ++i) {
        if (has_lower(i)) {
            const double d = w[i] - lower_[i];
            if (!(d > 0.0))
                return kInfinity;
            sum -= std::log(d);
        }
        if (has_upper(i)) {
            const double d = upper_[i] - w[i];
            if (!(d > 0.0))
                return kInfinity;
            sum -= std::log(d);
        }
    }
    return mu * sum;
}

void BarrierBounds::barrier_gradient(const Vector& w, double mu, Vector& gradient) const
{
    gradient.resize(size());
    for (int i = 0; i < size(); ++i) {
        double g = 0.0;
        if (has_lower(i))
            g -= mu / (w[i] - lower_[i]);
        if (has_upper(i))
            g += mu / (upper_[i] - w[i]);
        gradient[i] = g;
    }
}

void BarrierBounds::sigma(const Vector& w, const Vector& z_lower, const Vector& z_upper, Vector& sigma) const
{
    sigma.resize(size());
    for (int i = 0; i < size(); ++i) {
        double s = 0.0;
        if (has_lower(i))
            s += z_lower[i] / (w[i] - lower_[i]);
        if (has_upper(i))
            s += z_upper[i] / (upper_[i] - w[i]);
        sigma[i] = s;
    }
}

double BarrierBounds::max_step(const Vector& w, const Vector& dw, double tau) const
{
    double alpha = 1.0;
    for (int i = 0; i < size(); ++i) {
        if (has_lower(i) && dw[i] < 0.0)
            alpha = std::min(alpha, -tau * (w[i] - lower_[i]) / dw[i]);
        if (has_upper(i) && dw[i] > 0.0)
            alpha = std::min(alpha, tau * (upper_[i] - w[i]) / dw[i]);
    }
    return alpha;
}

double BarrierBounds::max_dual_step(const Vector& z, const Vector& dz, const Vector& mask, double tau) const
{
    double alpha = 1.0;
    for (int i = 0; i < size(); ++i)
        if (mask[i] != 0.0 && dz[i] < 0.0)
            alpha = std::min(alpha, -tau * z[i] / dz[i]);
    return alpha;
}

void BarrierBounds::safeguard(const Vector& w, double mu, Vector& z_lower, Vector& z_upper) const
{
    for (int i = 0; i < size(); ++i) {
        if (has_lower(i)) {
            const double d = w[i] - lower_[i];
            z_lower[i] = std::clamp(z_lower[i], mu / (kSigmaSafeguard * d), kSigmaSafeguard * mu / d);
        }
        if (has_upper(i)) {
            const double d = upper_[i] - w[i];
            z_upper[i] = std::clamp(z_upper[i], mu / (kSigmaSafeguard * d), kSigmaSafeguard * mu / d);
        }
    }
}

double BarrierBounds::complementarity(const Vector& w, const Vector& z_lower, const Vector& z_upper,
                                      double mu) const
{
    double worst = 0.0;
    for (int i = 0; i < size(); ++i) {
        if (has_lower(i))
            worst = std::max(worst, std::abs((w[i] - lower_[i]) * z_lower[i] - mu));
        if (has_upper(i))
            worst = std::max(worst, std::abs((upper_[i] - w[i]) * z_upper[i] - mu));
    }
    return worst;
}

void BarrierBounds::original(Vector& w) const
{
    for (int i = 0; i < size(); ++i) {
        if (has_lower(i))
            w[i] = std::max(w[i], original_lower_[i]);
        if (has_upper(i))
            w[i] = std::min(w[i], original_upper_[i]);
    }
}

} // namespace sinew
