#include "sinew/problems/difference_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr int kFinePoints = 5;   ///< x ± kη e_j for k = 0…5 (two fourth differences a side)
constexpr int kMaxHalvings = 8;  ///< one-sided steps h·2^-k, k = 0…8
/// Agreement within noise counts only where the noise allowance is at most
/// this share of the error floor (1e-4 of the derivative's largest entry):
/// a difference too noisy to resolve the entry settles nothing.
constexpr double kMaxNoiseShareOfFloor = 0.1;

/// max(0, |a − estimate| − allowance) / max(|estimate|, floor); infinite
/// when the estimate is not finite or the allowance too large to trust.
double relative_error(double analytic, double estimate, double allowance, double floor)
{
    if (allowance > kMaxNoiseShareOfFloor * floor)
        return std::numeric_limits<double>::infinity();
    const double error = std::max(0.0, std::abs(analytic - estimate) - allowance) / std::max(std::abs(estimate), floor);
    return std::isfinite(error) ? error : std::numeric_limits<double>::infinity();
}

Eigen::VectorXd moved(const Eigen::VectorXd& x, int j, double t)
{
    Eigen::VectorXd y = x;
    y[j] += t;
    return y;
}

/// σ_i of F_i along x_j: the smaller of the estimates from each side's
/// fourth differences (side[k] = F(x ± kη e_j), k = 0…kFinePoints), so that
/// a kink at x or within the grid on one side leaves the other clean; at
/// least ε·max |F_i|.
double noise_of(const std::vector<Eigen::VectorXd> (&sides)[2], int row)
{
    double sigma = std::numeric_limits<double>::infinity(), largest = 0.0;
    for (const std::vector<Eigen::VectorXd>& side : sides) {
        const auto v = [&](int k) { return side[static_cast<size_t>(k)][row]; };
        double sum_squares = 0.0;
        for (int m = 2; m + 2 <= kFinePoints; ++m) {
            const double fourth = v(m - 2) - 4 * v(m - 1) + 6 * v(m) - 4 * v(m + 1) + v(m + 2);  // Δ⁴
            sum_squares += fourth * fourth;
        }
        for (int k = 0; k <= kFinePoints; ++k)
            largest = std::max(largest, std::abs(v(k)));
        const double side_sigma = std::sqrt(sum_squares / (kFinePoints - 3) / 70.0);  // Var Δ⁴ = 70σ²
        if (std::isfinite(side_sigma))
            sigma = std::min(sigma, side_sigma);
    }
    return std::isfinite(sigma) ? std::max(sigma, kEpsilon * largest) : sigma;
}

/// The one-sided stage: entries not yet settled, both sides, halving h.
void one_sided(const PointFunction& F, const Eigen::VectorXd& x, int j, double h, const Eigen::VectorXd& F0,
               const std::vector<EntryToStudy>& entries, const std::vector<double>& sigma, double floor,
               double tolerance, std::vector<StudiedEntry>& out)
{
    const size_t count = entries.size();
    std::vector<char> agreed_before[2] = {std::vector<char>(count, 0), std::vector<char>(count, 0)};
    Eigen::VectorXd outer[2] = {F(moved(x, j, h)), F(moved(x, j, -h))};  // F(x ± h_k)
    for (int k = 0; k <= kMaxHalvings; ++k) {
        const double hk = std::ldexp(h, -k);
        const Eigen::VectorXd inner[2] = {F(moved(x, j, hk / 2)), F(moved(x, j, -hk / 2))};  // F(x ± h_k/2)
        bool unsettled = false;
        for (size_t e = 0; e < count; ++e) {
            if (out[e].outcome != StudyOutcome::disagrees)
                continue;
            const int row = entries[e].row;
            const double allowance = 3.0 * std::sqrt(26.0) * sigma[e] / hk;
            double estimate[2];
            bool agrees[2];
            for (int side = 0; side < 2; ++side) {
                const double sign = side == 0 ? 1.0 : -1.0;
                // (4F(x ± h/2) − 3F(x) − F(x ± h)) / (±h): exact for quadratics
                estimate[side] = (4.0 * inner[side][row] - 3.0 * F0[row] - outer[side][row]) / (sign * hk);
                agrees[side] = relative_error(entries[e].analytic, estimate[side], allowance, floor) <= tolerance;
            }
            for (int side = 0; side < 2; ++side) {
                if (agrees[side] && agreed_before[side][e] && out[e].outcome == StudyOutcome::disagrees) {
                    out[e].outcome = agrees[1 - side] ? StudyOutcome::both_sides : StudyOutcome::kink;
                    out[e].estimate = estimate[side];
                    out[e].relative_error = relative_error(entries[e].analytic, estimate[side], allowance, floor);
                }
                agreed_before[side][e] = agrees[side];
            }
            unsettled = unsettled || out[e].outcome == StudyOutcome::disagrees;
        }
        if (!unsettled)
            return;
        outer[0] = inner[0];
        outer[1] = inner[1];
    }
}

} // namespace

std::vector<StudiedEntry> study_column(const PointFunction& F, const Eigen::VectorXd& x, int j, double h,
                                       const Eigen::VectorXd& F_at_x, const std::vector<EntryToStudy>& entries,
                                       double floor, double tolerance)
{
    const double eta = 1e-2 * h;
    std::vector<Eigen::VectorXd> fine[2];
    for (int side = 0; side < 2; ++side)
        for (int k = 0; k <= kFinePoints; ++k)
            fine[side].push_back(k == 0 ? F_at_x : F(moved(x, j, (side == 0 ? k : -k) * eta)));
    std::vector<StudiedEntry> out(entries.size());
    std::vector<double> sigma(entries.size());
    bool unsettled = false;
    for (size_t e = 0; e < entries.size(); ++e) {
        sigma[e] = noise_of(fine, entries[e].row);
        const double allowance = 3.0 * std::sqrt(0.5) * sigma[e] / h;  // σ√2/(2h), three times
        out[e].estimate = entries[e].central;
        out[e].relative_error = relative_error(entries[e].analytic, entries[e].central, allowance, floor);
        if (out[e].relative_error <= tolerance)
            out[e].outcome = StudyOutcome::noise;
        else
            unsettled = true;
    }
    if (unsettled)
        one_sided(F, x, j, h, F_at_x, entries, sigma, floor, tolerance, out);
    for (size_t e = 0; e < entries.size(); ++e)
        if (out[e].outcome == StudyOutcome::disagrees) {  // report the central difference's own error
            out[e].estimate = entries[e].central;
            out[e].relative_error = relative_error(entries[e].analytic, entries[e].central, 0.0, floor);
        }
    return out;
}

} // namespace sinew
