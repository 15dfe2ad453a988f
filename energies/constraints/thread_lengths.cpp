#include "sinew/energies/constraints/thread_lengths.hpp"

#include "sinew/core/input_error.hpp"

#include <algorithm>
#include <set>
#include <string>

namespace sinew {
namespace {

const std::string kWho = "thread lengths";

std::string node_label(int polyline, int position)
{
    return kWho + ": polyline " + std::to_string(polyline) + ", position " + std::to_string(position);
}

} // namespace

ThreadLengths::ThreadLengths(int num_nodes, int dimension, const Eigen::VectorXd& rest_coordinates,
                             const std::vector<std::vector<int>>& polylines)
    : dimension_(dimension)
{
    if (dimension != 2 && dimension != 3)
        throw InputError(kWho + ": dimension is " + std::to_string(dimension) + ", expected 2 or 3");
    if (num_nodes < 0 || rest_coordinates.size() != static_cast<Eigen::Index>(num_nodes) * dimension)
        throw InputError(kWho + ": " + std::to_string(rest_coordinates.size()) + " rest coordinates for " +
                         std::to_string(num_nodes) + " nodes in " + std::to_string(dimension) + "D");
    if (!rest_coordinates.allFinite())
        throw InputError(kWho + ": a rest coordinate is not finite");

    std::set<std::pair<int, int>> seen;  // segments as (min, max)
    for (int p = 0; p < static_cast<int>(polylines.size()); ++p) {
        const std::vector<int>& nodes = polylines[p];
        if (nodes.size() < 2)
            throw InputError(kWho + ": polyline " + std::to_string(p) + " has " + std::to_string(nodes.size()) +
                             " node" + (nodes.size() == 1 ? "" : "s") + ", a thread needs at least 2");
        for (int s = 0; s < static_cast<int>(nodes.size()); ++s)
            if (nodes[s] < 0 || nodes[s] >= num_nodes)
                throw InputError(node_label(p, s) + ": node " + std::to_string(nodes[s]) + " is outside [0, " +
                                 std::to_string(num_nodes) + ")");
        for (int s = 1; s < static_cast<int>(nodes.size()); ++s) {
            const int i = nodes[s - 1];
            const int j = nodes[s];
            if (i == j)
                throw InputError(node_label(p, s) + ": node " + std::to_string(j) + " repeats the node before it");
            // L_ij = |X_j − X_i|, the rest length the segment keeps.
            const double length = (rest_coordinates.segment(j * dimension, dimension) -
                                   rest_coordinates.segment(i * dimension, dimension))
                                      .norm();
            if (!(length > 0.0))
                throw InputError(node_label(p, s) + ": segment (" + std::to_string(i) + ", " + std::to_string(j) +
                                 ") has zero rest length");
            if (!seen.emplace(std::min(i, j), std::max(i, j)).second)
                throw InputError(node_label(p, s) + ": segment (" + std::to_string(i) + ", " + std::to_string(j) +
                                 ") is listed twice");
            segments_.emplace_back(i, j);
            rest_lengths_.push_back(length);
        }
    }

    for (int k = 0; k < num_constraints(); ++k) {
        const auto [i, j] = segments_[k];
        for (int m = 0; m < dimension_; ++m)
            jacobian_.add(k, i * dimension_ + m);
        for (int m = 0; m < dimension_; ++m)
            jacobian_.add(k, j * dimension_ + m);
        // ∇²c = 2 [I −I; −I I]: diagonal of i, of j, and the coupling i–j, per coordinate.
        for (int m = 0; m < dimension_; ++m) {
            const int p = i * dimension_ + m;
            const int q = j * dimension_ + m;
            hessian_.add(p, p);
            hessian_.add(q, q);
            hessian_.add(std::max(p, q), std::min(p, q));
        }
    }
}

void ThreadLengths::values(ConstVectorRef x, VectorRef c)
{
    for (int k = 0; k < num_constraints(); ++k) {
        const auto [i, j] = segments_[k];
        const double length = rest_lengths_[k];
        // c = |x_j − x_i|² / L² − 1
        c[k] = (x.segment(j * dimension_, dimension_) - x.segment(i * dimension_, dimension_)).squaredNorm() /
                   (length * length) -
               1.0;
    }
}

void ThreadLengths::jacobian_values(ConstVectorRef x, VectorRef values)
{
    int entry = 0;
    for (int k = 0; k < num_constraints(); ++k) {
        const auto [i, j] = segments_[k];
        const double scale = 2.0 / (rest_lengths_[k] * rest_lengths_[k]);
        for (int m = 0; m < dimension_; ++m)  // ∂c/∂x_i = −2 (x_j − x_i) / L²
            values[entry++] = -scale * (x[j * dimension_ + m] - x[i * dimension_ + m]);
        for (int m = 0; m < dimension_; ++m)  // ∂c/∂x_j = 2 (x_j − x_i) / L²
            values[entry++] = scale * (x[j * dimension_ + m] - x[i * dimension_ + m]);
    }
}

void ThreadLengths::hessian_values(ConstVectorRef, ConstVectorRef lambda, Projection projection, VectorRef values)
{
    int entry = 0;
    for (int k = 0; k < num_constraints(); ++k) {
        // λ∇²c = 2λ/L² [I −I; −I I], PSD up to the sign of λ: projected, max(λ, 0).
        const double weight = (projection == Projection::clamp ? std::max(lambda[k], 0.0) : lambda[k]) /
                              (rest_lengths_[k] * rest_lengths_[k]);
        for (int m = 0; m < dimension_; ++m) {
            values[entry++] = 2.0 * weight;
            values[entry++] = 2.0 * weight;
            values[entry++] = -2.0 * weight;
        }
    }
}

} // namespace sinew
