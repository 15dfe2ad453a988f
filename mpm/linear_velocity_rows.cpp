#include "sinew/mpm/linear_velocity_rows.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseQR>

#include <algorithm>
#include <vector>

namespace sinew {

LinearVelocityRows independent_rows(const LinearVelocityRows& rows)
{
    if (rows.rows() == 0)
        return rows;
    const Eigen::SparseMatrix<double> transposed = rows.B.transpose();  // n × m: a column per row
    Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr;
    qr.compute(transposed);
    const auto rank = static_cast<int>(qr.rank());
    if (rank == rows.rows())
        return rows;
    std::vector<int> kept;
    for (int k = 0; k < rank; ++k)
        kept.push_back(qr.colsPermutation().indices()[k]);
    std::sort(kept.begin(), kept.end());
    LinearVelocityRows out;
    out.B.resize(rank, rows.B.cols());
    out.rhs.resize(rank);
    std::vector<Eigen::Triplet<double>> entries;
    for (int r = 0; r < rank; ++r) {
        const int row = kept[static_cast<std::size_t>(r)];
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows.B, row); it; ++it)
            entries.emplace_back(r, static_cast<int>(it.col()), it.value());
        out.rhs[r] = rows.rhs[row];
    }
    out.B.setFromTriplets(entries.begin(), entries.end());
    return out;
}

} // namespace sinew
