#include "sinew/solvers/interior/filter_line_search.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

constexpr double kDelta = 1.0;        ///< δ of the switching condition
constexpr double kSTheta = 1.1;       ///< s_θ
constexpr double kSPhi = 2.3;         ///< s_φ
constexpr double kEta = 1e-8;         ///< η_φ, Armijo constant
constexpr double kGammaAlpha = 0.05;  ///< γ_α, safety factor of α_min
constexpr double kSocReduction = 0.99;  ///< κ_soc
constexpr int kMaxCorrections = 4;      ///< p_max

} // namespace

FilterLineSearch::FilterLineSearch(double theta0)
    : theta_max_(1e4 * std::max(1.0, theta0)), theta_min_(1e-4 * std::max(1.0, theta0))
{
}

bool FilterLineSearch::switching(double theta_k, double slope, double alpha) const
{
    // α (−∇φᵀd)^{s_φ} > δ θ_k^{s_θ}, eq. 19.
    return slope < 0.0 && alpha * std::pow(-slope, kSPhi) > kDelta * std::pow(theta_k, kSTheta);
}

std::optional<FilterStepKind> FilterLineSearch::judge(const TrialMeasures& current, const TrialMeasures& point,
                                                      double slope, double alpha) const
{
    if (!std::isfinite(point.phi) || !(point.theta <= theta_max_) || !filter_.accepts(point.theta, point.phi))
        return std::nullopt;
    if (current.theta <= theta_min_ && switching(current.theta, slope, alpha)) {
        if (point.phi <= current.phi + kEta * alpha * slope)  // Armijo, eq. 20
            return FilterStepKind::f_type;
        return std::nullopt;
    }
    if (improves_on(point.theta, point.phi, current.theta, current.phi))
        return FilterStepKind::h_type;
    return std::nullopt;
}

double FilterLineSearch::smallest_alpha(const TrialMeasures& current, double slope) const
{
    // α_min of eq. 23.
    const double gt = Filter::kGammaTheta, gp = Filter::kGammaPhi;
    if (!(slope < 0.0))
        return kGammaAlpha * gt;
    double bound = std::min(gt, gp * current.theta / -slope);
    if (current.theta <= theta_min_)
        bound = std::min(bound, kDelta * std::pow(current.theta, kSTheta) / std::pow(-slope, kSPhi));
    return kGammaAlpha * bound;
}

FilterStep FilterLineSearch::search(const TrialMeasures& current, double slope, double alpha_max,
                                    const std::function<TrialMeasures(double alpha)>& trial,
                                    const std::function<std::optional<TrialMeasures>(int k)>& correction)
{
    // Below α_min, or once α stops changing x (θ_k = 0: α_min = 0), give up.
    const double alpha_min = std::max(smallest_alpha(current, slope), 1e-16 * alpha_max);
    FilterStep step;
    auto accept = [&](FilterStepKind kind, double alpha) {
        step.kind = kind;
        step.alpha = alpha;
        if (kind == FilterStepKind::h_type)
            filter_.add(current.theta, current.phi);
        return step;
    };
    for (double alpha = alpha_max; alpha >= alpha_min; alpha *= 0.5, ++step.backtracks) {
        const TrialMeasures point = trial(alpha);
        if (const auto kind = judge(current, point, slope, alpha))
            return accept(*kind, alpha);
        if (step.backtracks > 0 || !(point.theta >= current.theta))
            continue;
        // Second-order corrections of the first trial (§2.4): accepted by the
        // same tests at α_max; stopped once θ no longer falls by κ_soc.
        double theta_before = point.theta;
        for (int k = 1; k <= kMaxCorrections; ++k) {
            const auto corrected = correction(k);
            if (!corrected || !std::isfinite(corrected->theta))
                break;
            if (const auto kind = judge(current, *corrected, slope, alpha_max)) {
                step.second_order_correction = true;
                return accept(*kind, alpha_max);
            }
            if (corrected->theta > kSocReduction * theta_before)
                break;
            theta_before = corrected->theta;
        }
    }
    step.kind = current.theta > 0.0 ? FilterStepKind::restoration : FilterStepKind::no_decrease;
    return step;
}

} // namespace sinew
