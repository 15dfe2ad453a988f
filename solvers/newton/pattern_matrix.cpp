#include "sinew/solvers/newton/pattern_matrix.hpp"

#include <algorithm>
#include <stdexcept>

namespace sinew {

PatternMatrix::PatternMatrix(const SparsityPattern& pattern, int size) : matrix_(size, size)
{
    // Structure: the pattern's entries plus the whole diagonal, each once.
    std::vector<Eigen::Triplet<double, int>> entries;
    entries.reserve(static_cast<size_t>(pattern.nonzeros() + size));
    for (int k = 0; k < pattern.nonzeros(); ++k)
        entries.emplace_back(pattern.rows[static_cast<size_t>(k)], pattern.cols[static_cast<size_t>(k)], 0.0);
    for (int i = 0; i < size; ++i)
        entries.emplace_back(i, i, 0.0);
    matrix_.setFromTriplets(entries.begin(), entries.end());
    matrix_.makeCompressed();

    auto nonzero_of = [this](int row, int col) {
        const int* begin = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col];
        const int* end = matrix_.innerIndexPtr() + matrix_.outerIndexPtr()[col + 1];
        const int* found = std::lower_bound(begin, end, row);
        if (found == end || *found != row)
            throw std::logic_error("PatternMatrix: entry missing from its own structure");
        return static_cast<int>(found - matrix_.innerIndexPtr());
    };
    value_index_.resize(static_cast<size_t>(pattern.nonzeros()));
    for (int k = 0; k < pattern.nonzeros(); ++k)
        value_index_[static_cast<size_t>(k)] =
            nonzero_of(pattern.rows[static_cast<size_t>(k)], pattern.cols[static_cast<size_t>(k)]);
    diagonal_index_.resize(static_cast<size_t>(size));
    for (int i = 0; i < size; ++i)
        diagonal_index_[static_cast<size_t>(i)] = nonzero_of(i, i);
}

void PatternMatrix::fill(const Eigen::VectorXd& pattern_values)
{
    double* values = matrix_.valuePtr();
    std::fill(values, values + matrix_.nonZeros(), 0.0);
    for (size_t k = 0; k < value_index_.size(); ++k)
        values[value_index_[k]] += pattern_values[static_cast<Eigen::Index>(k)];
}

void PatternMatrix::shift_diagonal(double shift)
{
    for (int index : diagonal_index_)
        matrix_.valuePtr()[index] += shift;
}

void PatternMatrix::fix_variables(const std::vector<char>& fixed)
{
    for (int col = 0; col < matrix_.outerSize(); ++col)
        for (SparseMatrix::InnerIterator entry(matrix_, col); entry; ++entry) {
            const auto row = static_cast<size_t>(entry.row());
            if (fixed[row] || fixed[static_cast<size_t>(col)])
                entry.valueRef() = entry.row() == col ? 1.0 : 0.0;
        }
}

} // namespace sinew
