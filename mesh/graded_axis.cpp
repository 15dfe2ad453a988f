#include "sinew/mesh/graded_axis.hpp"

#include "sinew/core/input_error.hpp"

#include <cmath>
#include <limits>

namespace sinew {
namespace {

/// h₀ of k cells growing by q that fill `length`: h₀ Σ_{i<k} qⁱ = length.
double first_width(double length, int k, double q)
{
    const double sum = q == 1.0 ? k : (std::pow(q, k) - 1.0) / (q - 1.0);
    return length / sum;
}

/// Nodes from `start` moving by `direction` (±1) over k cells from h₀ growing by q; the last node is `end` exactly.
void append_side(std::vector<double>& nodes, double start, double end, int k, double q)
{
    const double h0 = first_width(std::abs(end - start), k, q);
    const double direction = end > start ? 1.0 : -1.0;
    double offset = 0.0, width = h0;
    for (int i = 1; i < k; ++i) {
        offset += width;
        nodes.push_back(start + direction * offset);
        width *= q;
    }
    nodes.push_back(end);
}

} // namespace

std::vector<double> graded_axis(double lower, double upper, int n, double focus, double ratio)
{
    if (n < 1)
        throw InputError("graded axis: " + std::to_string(n) + " cells (at least 1)");
    if (!(std::isfinite(lower) && std::isfinite(upper) && lower < upper))
        throw InputError("graded axis: lower < upper must hold, both finite");
    if (!(std::isfinite(focus) && focus >= lower && focus <= upper))
        throw InputError("graded axis: the focus is outside [lower, upper]");
    if (!(ratio >= 1.0 && ratio <= kMaxGradingRatio))
        throw InputError("graded axis: ratio must be in [1, " + std::to_string(kMaxGradingRatio) + "]");
    const double left = focus - lower, right = upper - focus;
    // The split of the n cells whose two first widths differ least.
    int best = left > 0.0 ? (right > 0.0 ? 1 : n) : 0;
    double mismatch = std::numeric_limits<double>::infinity();
    if (left > 0.0 && right > 0.0)
        for (int k = 1; k < n; ++k) {
            const double a = first_width(left, k, ratio), b = first_width(right, n - k, ratio);
            const double m = std::abs(std::log(a / b));
            if (m < mismatch) {
                mismatch = m;
                best = k;
            }
        }
    if (left > 0.0 && right > 0.0 && n < 2)
        throw InputError("graded axis: a focus inside the axis needs at least 2 cells");
    std::vector<double> nodes{lower};
    if (best > 0) {
        std::vector<double> side{focus};
        append_side(side, focus, lower, best, ratio);  // focus → lower
        nodes.assign(side.rbegin(), side.rend());
    }
    if (best < n)
        append_side(nodes, focus, upper, n - best, ratio);
    for (size_t i = 1; i < nodes.size(); ++i)
        if (!(nodes[i] > nodes[i - 1]))
            throw InputError("graded axis: cells too thin to resolve near the focus");
    return nodes;
}

} // namespace sinew
