#include "sinew/solvers/interior/barrier_parameter.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

constexpr double kKappaEpsilon = 10.0;  ///< κ_ε
constexpr double kKappaMu = 0.2;        ///< κ_μ
constexpr double kThetaMu = 1.5;        ///< θ_μ
constexpr double kReduction = 0.9999;   ///< Ipopt's adaptive_mu_kkterror_red_fact
constexpr size_t kReferences = 4;       ///< Ipopt's num_refs_max
constexpr double kMonotoneStart = 0.8;  ///< Ipopt's adaptive_mu_monotone_init_factor

} // namespace

BarrierParameter::BarrierParameter(Rule rule, double initial, double smallest)
    : rule_(rule), mu_(std::max(initial, smallest)), smallest_(smallest)
{
}

double BarrierParameter::fraction_to_boundary() const { return std::max(0.99, 1.0 - mu_); }

std::string BarrierParameter::mode() const
{
    if (rule_ == Rule::monotone)
        return "monotone";
    return free_mode_ ? "adaptive (free)" : "adaptive (monotone safeguard)";
}

bool BarrierParameter::monotone_decrease(const BarrierMeasures& measures)
{
    const double before = mu_;
    while (mu_ > smallest_ && measures.barrier_error(mu_) <= kKappaEpsilon * mu_)
        mu_ = std::max(smallest_, std::min(kKappaMu * mu_, std::pow(mu_, kThetaMu)));
    return mu_ != before;
}

void BarrierParameter::force_decrease()
{
    mu_ = std::max(smallest_, std::min(kKappaMu * mu_, std::pow(mu_, kThetaMu)));
}

bool BarrierParameter::sufficient_progress(double error) const
{
    if (references_.empty())
        return true;
    return error <= kReduction * *std::max_element(references_.begin(), references_.end());
}

void BarrierParameter::remember(double error)
{
    references_.push_back(error);
    if (references_.size() > kReferences)
        references_.pop_front();
}

bool BarrierParameter::update(const BarrierMeasures& measures)
{
    if (rule_ == Rule::monotone)
        return monotone_decrease(measures);
    const double before = mu_;
    if (free_mode_ && !sufficient_progress(measures.optimality_error)) {
        free_mode_ = false;
        mu_ = std::max(smallest_, kMonotoneStart * measures.average_complementarity);
        return mu_ != before;
    }
    if (!free_mode_) {
        const bool solved = measures.barrier_error(mu_) <= kKappaEpsilon * mu_;
        if (!(solved && sufficient_progress(measures.optimality_error)))
            return monotone_decrease(measures);
        free_mode_ = true;
    }
    remember(measures.optimality_error);
    // LOQO: σ = 0.1 min(0.05 (1 − ξ)/ξ, 2)³ with ξ = min/average complementarity.
    const double average = measures.average_complementarity;
    const double xi = average > 0.0 ? measures.smallest_complementarity / average : 1.0;
    const double sigma = xi > 0.0 ? 0.1 * std::pow(std::min(0.05 * (1.0 - xi) / xi, 2.0), 3.0) : 0.8;
    mu_ = std::max(smallest_, sigma * average);
    return mu_ != before;
}

} // namespace sinew
