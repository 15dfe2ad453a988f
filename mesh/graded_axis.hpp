#pragma once
#include <vector>

namespace sinew {

/// The largest ratio between neighbouring cell widths a graded axis takes.
constexpr double kMaxGradingRatio = 2.0;

/// The n + 1 node coordinates of an axis [lower, upper] cut into n cells
/// whose widths grow geometrically, by `ratio` from cell to cell, away from
/// the coordinate `focus` ∈ [lower, upper]: the cells next to the focus are
/// the finest (a contact zone, a crack tip), and a node sits on the focus
/// unless it is an end. The n cells are shared between the two sides so that
/// both start from nearly the same width h₀ (each side's h₀ fits its length
/// exactly: h₀(qᵏ − 1)/(q − 1) = side length for k cells). ratio = 1 gives
/// equal cells. Ends are exact. InputError for n < 1, lower < upper false,
/// a focus outside [lower, upper], a ratio outside [1, kMaxGradingRatio], or
/// a side too short for a cell.
std::vector<double> graded_axis(double lower, double upper, int n, double focus, double ratio);

} // namespace sinew
