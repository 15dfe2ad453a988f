#include "sinew/bench/performance_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace sinew {

std::vector<std::vector<double>> performance_profile(const std::vector<StrategyCosts>& strategies,
                                                     const std::vector<double>& taus)
{
    if (strategies.empty())
        return {};
    const size_t problems = strategies.front().costs.size();
    for (const StrategyCosts& s : strategies)
        if (s.costs.size() != problems)
            throw std::invalid_argument("performance_profile: every strategy needs one cost per problem");
    // The best cost on each problem; a zero cost (an iteration count of 0 at a
    // starting point that is already optimal) is compared as 1, so that ratios stay finite.
    std::vector<double> best(problems, kUnsolved);
    for (const StrategyCosts& s : strategies)
        for (size_t p = 0; p < problems; ++p)
            best[p] = std::min(best[p], std::max(s.costs[p], 1e-300));
    std::vector<std::vector<double>> rho;
    for (const StrategyCosts& s : strategies) {
        std::vector<double> row;
        for (double tau : taus) {
            int within = 0;
            for (size_t p = 0; p < problems; ++p)
                if (std::isfinite(s.costs[p]) && std::max(s.costs[p], 1e-300) <= tau * best[p])
                    ++within;
            row.push_back(problems == 0 ? 0.0 : static_cast<double>(within) / static_cast<double>(problems));
        }
        rho.push_back(row);
    }
    return rho;
}

std::string performance_profile_table(const std::vector<StrategyCosts>& strategies, const std::vector<double>& taus)
{
    const auto rho = performance_profile(strategies, taus);
    std::ostringstream out;
    out << "| strategy |";
    for (double tau : taus)
        out << " ρ(" << tau << ") |";
    out << "\n|---|";
    for (size_t t = 0; t < taus.size(); ++t)
        out << "---:|";
    out << "\n";
    for (size_t s = 0; s < strategies.size(); ++s) {
        out << "| " << strategies[s].strategy << " |";
        for (double value : rho[s]) {
            char cell[32];
            std::snprintf(cell, sizeof cell, " %.2f |", value);
            out << cell;
        }
        out << "\n";
    }
    return out.str();
}

namespace {

/// 1, every finite ratio r_{p,s} = cost / best cost, and twice the largest, sorted.
std::vector<double> profile_breakpoints(const std::vector<StrategyCosts>& strategies)
{
    std::vector<double> taus = {1.0};
    if (strategies.empty())
        return taus;
    for (size_t p = 0; p < strategies.front().costs.size(); ++p) {
        double best = kUnsolved;
        for (const StrategyCosts& s : strategies)
            best = std::min(best, std::max(s.costs[p], 1e-300));
        for (const StrategyCosts& s : strategies)
            if (std::isfinite(s.costs[p]))
                taus.push_back(std::max(s.costs[p], 1e-300) / best);
    }
    std::sort(taus.begin(), taus.end());
    taus.erase(std::unique(taus.begin(), taus.end()), taus.end());
    taus.push_back(2.0 * taus.back());
    return taus;
}

} // namespace

Plot performance_profile_plot(const std::vector<StrategyCosts>& strategies, const std::string& title)
{
    const std::vector<double> taus = profile_breakpoints(strategies);
    const auto rho = performance_profile(strategies, taus);
    Plot plot{title, "tau (cost within tau times the best)", "fraction of problems solved", true, false, true, {}};
    for (size_t s = 0; s < strategies.size(); ++s)
        plot.series.push_back({strategies[s].strategy, taus, rho[s]});
    return plot;
}

} // namespace sinew
