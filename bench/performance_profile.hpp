#pragma once
#include "sinew/runs/gnuplot_plot.hpp"

#include <limits>
#include <string>
#include <vector>

namespace sinew {

/// One strategy's cost on each problem of a suite (iterations, seconds, …);
/// +∞ where it did not solve the problem.
struct StrategyCosts {
    std::string strategy;
    std::vector<double> costs;  ///< one per problem, in the same order for every strategy
};

/// Dolan & Moré performance profiles (Math. Program. 91, 2002): for strategy
/// s, ρ_s(τ) = the fraction of problems p with r_{p,s} ≤ τ, where
/// r_{p,s} = cost_{p,s} / min_{s'} cost_{p,s'}. A problem no strategy solved
/// counts against every one. Returns ρ_s(τ) for each strategy (rows) and τ (columns).
std::vector<std::vector<double>> performance_profile(const std::vector<StrategyCosts>& strategies,
                                                     const std::vector<double>& taus);

/// A markdown table: strategy | ρ(τ₁) | ρ(τ₂) | …
std::string performance_profile_table(const std::vector<StrategyCosts>& strategies, const std::vector<double>& taus);

/// The profiles as a step plot against τ (log scale) from 1 to twice the
/// largest finite ratio r_{p,s}, with a step at every ratio that occurs.
Plot performance_profile_plot(const std::vector<StrategyCosts>& strategies, const std::string& title);

inline constexpr double kUnsolved = std::numeric_limits<double>::infinity();

} // namespace sinew
