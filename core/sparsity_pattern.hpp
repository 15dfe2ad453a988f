#pragma once
#include <vector>

namespace sinew {

/// Positions of the nonzeros of a sparse matrix, as (row, col) pairs, fixed at
/// setup. Values are passed separately, in the same order.
struct SparsityPattern {
    std::vector<int> rows;
    std::vector<int> cols;
    int nonzeros() const { return static_cast<int>(rows.size()); }
    void add(int row, int col)
    {
        rows.push_back(row);
        cols.push_back(col);
    }
};

} // namespace sinew
