#include "sinew/energies/potentials/hessian_pattern.hpp"

#include "sinew/core/input_error.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace sinew {
namespace {

/// Key of the node pair (lower, higher), lower < higher, sorting by lower first.
std::int64_t pair_key(int lower, int higher)
{
    return (static_cast<std::int64_t>(lower) << 32) | static_cast<std::int64_t>(higher);
}

void check_stencil(const Stencils& stencils, int s, int num_nodes)
{
    for (int a = 0; a < stencils.rows(); ++a) {
        const int node = stencils(a, s);
        if (node < 0 || node >= num_nodes)
            throw InputError("Hessian stencil " + std::to_string(s) + " names node " + std::to_string(node) +
                             ", outside [0, " + std::to_string(num_nodes) + ")");
        for (int b = 0; b < a; ++b)
            if (stencils(b, s) == node)
                throw InputError("Hessian stencil " + std::to_string(s) + " lists node " + std::to_string(node) +
                                 " twice (a degenerate element)");
    }
}

} // namespace

HessianPattern::HessianPattern(int dimension, int num_nodes, const std::vector<const Stencils*>& stencil_sets)
    : dimension_(dimension), num_nodes_(num_nodes)
{
    if (dimension < 1 || num_nodes < 0)
        throw InputError("Hessian pattern: dimension " + std::to_string(dimension) + " and node count " +
                         std::to_string(num_nodes) + " are not valid");

    std::vector<std::int64_t> pairs;
    for (const Stencils* stencils : stencil_sets) {
        const int n = static_cast<int>(stencils->rows());
        pairs.reserve(pairs.size() + static_cast<std::size_t>(stencils->cols()) * n * (n - 1) / 2);
        for (int s = 0; s < stencils->cols(); ++s) {
            check_stencil(*stencils, s, num_nodes);
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < a; ++b) {
                    const int i = (*stencils)(a, s);
                    const int j = (*stencils)(b, s);
                    pairs.push_back(pair_key(std::min(i, j), std::max(i, j)));
                }
        }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

    neighbor_starts_.assign(static_cast<std::size_t>(num_nodes) + 1, 0);
    neighbors_.resize(pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        ++neighbor_starts_[static_cast<std::size_t>(pairs[k] >> 32) + 1];
        neighbors_[k] = static_cast<int>(pairs[k] & 0xffffffff);
    }
    for (int j = 0; j < num_nodes; ++j)
        neighbor_starts_[j + 1] += neighbor_starts_[j];

    const int d = dimension;
    column_starts_.assign(static_cast<std::size_t>(num_nodes) * d + 1, 0);
    for (int j = 0; j < num_nodes; ++j) {
        const int degree = neighbor_starts_[j + 1] - neighbor_starts_[j];
        for (int m = 0; m < d; ++m)
            column_starts_[j * d + m + 1] = column_starts_[j * d + m] + (d - m) + d * degree;
    }
    const int total = column_starts_.back();
    rows_.reserve(total);
    cols_.reserve(total);
    for (int j = 0; j < num_nodes; ++j)
        for (int m = 0; m < d; ++m) {
            const int col = j * d + m;
            for (int n = m; n < d; ++n) {
                rows_.push_back(j * d + n);
                cols_.push_back(col);
            }
            for (int k = neighbor_starts_[j]; k < neighbor_starts_[j + 1]; ++k)
                for (int n = 0; n < d; ++n) {
                    rows_.push_back(neighbors_[k] * d + n);
                    cols_.push_back(col);
                }
        }
}

int HessianPattern::block_entry(int node_i, int node_j, int n, int m) const
{
    const int start = column_starts_[node_j * dimension_ + m];
    if (node_i == node_j)
        return n >= m ? start + (n - m) : -1;
    const auto first = neighbors_.begin() + neighbor_starts_[node_j];
    const auto last = neighbors_.begin() + neighbor_starts_[node_j + 1];
    const auto found = std::lower_bound(first, last, node_i);
    if (found == last || *found != node_i)
        return -1;
    const int rank = static_cast<int>(found - first);
    return start + (dimension_ - m) + dimension_ * rank + n;
}

int HessianPattern::find(int row, int col) const
{
    const int size = num_coordinates();
    if (row < col || col < 0 || row >= size)
        return -1;
    return block_entry(row / dimension_, col / dimension_, row % dimension_, col % dimension_);
}

StencilSlots HessianPattern::slots(const Stencils& stencils) const
{
    const int d = dimension_;
    const int n = d * static_cast<int>(stencils.rows());
    StencilSlots table(n * (n + 1) / 2, stencils.cols());
    for (int s = 0; s < stencils.cols(); ++s) {
        check_stencil(stencils, s, num_nodes_);
        int k = 0;
        for (int q = 0; q < n; ++q)
            for (int p = q; p < n; ++p) {
                const int node_p = stencils(p / d, s);
                const int node_q = stencils(q / d, s);
                const int slot = node_p >= node_q ? block_entry(node_p, node_q, p % d, q % d)
                                                  : block_entry(node_q, node_p, q % d, p % d);
                if (slot < 0)
                    throw std::logic_error("Hessian stencil " + std::to_string(s) +
                                           " is not covered by the pattern it was given");
                table(k++, s) = slot;
            }
    }
    return table;
}

} // namespace sinew
