#include "sinew/solvers/linear/symmetric_csr.hpp"

#include <algorithm>
#include <numeric>

namespace sinew {

SymmetricCsr::SymmetricCsr(const SparseMatrix& lower)
    : row_starts_(static_cast<size_t>(lower.rows()) + 1, 0), below_(static_cast<size_t>(lower.nonZeros()), -1),
      above_(static_cast<size_t>(lower.nonZeros()), -1)
{
    const int* outer = lower.outerIndexPtr();
    const int* inner = lower.innerIndexPtr();
    const int n = static_cast<int>(lower.cols());
    for (int j = 0; j < n; ++j)
        for (int k = outer[j]; k < outer[j + 1]; ++k) {
            const int i = inner[k];
            if (i < j)
                continue;  // above the diagonal: not read
            ++row_starts_[static_cast<size_t>(i) + 1];  // (i, j)
            if (i != j)
                ++row_starts_[static_cast<size_t>(j) + 1];  // (j, i)
        }
    std::partial_sum(row_starts_.begin(), row_starts_.end(), row_starts_.begin());
    // Each row's slots in the order the entries come, each slot remembering
    // its entry k and side (2k below or on the diagonal, 2k + 1 above)...
    std::vector<int> origin(static_cast<size_t>(row_starts_.back()));
    columns_.resize(origin.size());
    std::vector<int> next(row_starts_.begin(), row_starts_.end() - 1);
    for (int j = 0; j < n; ++j)
        for (int k = outer[j]; k < outer[j + 1]; ++k) {
            const int i = inner[k];
            if (i < j)
                continue;
            columns_[next[i]] = j;
            origin[next[i]++] = 2 * k;
            if (i != j) {
                columns_[next[j]] = i;
                origin[next[j]++] = 2 * k + 1;
            }
        }
    // ...then sorted by column within the row, as CSR wants, and the map
    // read off the sorted slots.
    std::vector<int> order;
    std::vector<int> sorted_columns, sorted_origin;
    for (int r = 0; r < n; ++r) {
        const int start = row_starts_[r], count = row_starts_[r + 1] - start;
        order.resize(static_cast<size_t>(count));
        std::iota(order.begin(), order.end(), start);
        std::sort(order.begin(), order.end(), [&](int a, int b) { return columns_[a] < columns_[b]; });
        sorted_columns.resize(order.size());
        sorted_origin.resize(order.size());
        for (int s = 0; s < count; ++s) {
            sorted_columns[s] = columns_[order[s]];
            sorted_origin[s] = origin[order[s]];
        }
        for (int s = 0; s < count; ++s) {
            columns_[start + s] = sorted_columns[s];
            const int k = sorted_origin[s] / 2;
            (sorted_origin[s] % 2 == 0 ? below_ : above_)[k] = start + s;
        }
    }
}

void SymmetricCsr::fill(const SparseMatrix& lower, double* values) const
{
    const double* entries = lower.valuePtr();
    for (size_t k = 0; k < below_.size(); ++k) {
        if (below_[k] < 0)
            continue;  // above the diagonal: not read
        values[below_[k]] = entries[k];  // A(i, j)
        if (above_[k] >= 0)
            values[above_[k]] = entries[k];  // A(j, i) = A(i, j)
    }
}

} // namespace sinew
