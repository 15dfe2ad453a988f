#include "sinew/mpm/inextensibility/inextensibility_rows.hpp"

#include "sinew/mpm/inextensibility/cell_basis.hpp"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sinew {
namespace {

/// A cell's index packed into 64 bits (each axis offset into [0, 2²¹)).
template <int Dim>
std::uint64_t cell_key(const Eigen::Matrix<int, Dim, 1>& cell)
{
    std::uint64_t key = 0;
    for (int d = 0; d < Dim; ++d)
        key = (key << 21) | static_cast<std::uint64_t>(cell[d] + (1 << 20));
    return key;
}

} // namespace

template <int Dim>
LinearVelocityRows inextensibility_rows(const Particles<Dim>& particles, const GridVelocityMap<Dim>& map, double dx,
                                        const InextensibilitySettings& settings)
{
    using Vector = Eigen::Matrix<double, Dim, 1>;
    std::unordered_map<std::uint64_t, int> row_of_cell;
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> weight;  // W_c
    std::vector<double> rhs;     // −Σ_p V Γ (b·a₀) aᵀ offset
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        if (!settings.carries(particles.material[i]))
            continue;
        const Vector& a0 = particles.point[i].fiber;
        const Vector a = particles.F[i] * a0;  // a = Fⁿ a₀
        const auto* couplings = map.couplings(p);
        cell_stencil<Dim>(particles.x[i], dx).for_each([&](const Eigen::Matrix<int, Dim, 1>& cell, double gamma) {
            if (!(gamma > 0.0))
                return;
            const auto found = row_of_cell.emplace(cell_key<Dim>(cell), static_cast<int>(weight.size()));
            if (found.second) {
                weight.push_back(0.0);
                rhs.push_back(0.0);
            }
            const int row = found.first->second;
            const double w = particles.volume[i] * gamma;  // V_p⁰ Γ_c(x_p)
            weight[static_cast<std::size_t>(row)] += w;
            for (int t = 0; t < map.stencil_nodes(); ++t) {
                const int node = couplings[t].node;
                if (node < 0)
                    continue;
                const double along = w * couplings[t].b.dot(a0);  // V Γ (b_ip·a₀) = V Γ (q_ip·a)
                const NodeVelocityFrame<Dim>& frame = map.frame(node);
                rhs[static_cast<std::size_t>(row)] -= along * a.dot(frame.offset);  // offset_i to the right
                for (int k = 0; k < frame.basis.cols(); ++k)
                    entries.emplace_back(row, map.first_variable(node) + k, along * a.dot(frame.basis.col(k)));
            }
        });
    }
    Eigen::SparseMatrix<double, Eigen::RowMajor> all(static_cast<Eigen::Index>(weight.size()), map.variables());
    all.setFromTriplets(entries.begin(), entries.end());
    // Keep the rows with a free unknown, each divided by W_c.
    std::vector<Eigen::Triplet<double>> kept;
    std::vector<double> kept_rhs;
    for (Eigen::Index r = 0; r < all.rows(); ++r) {
        bool free = false;
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(all, r); it; ++it)
            free = free || it.value() != 0.0;
        if (!free)
            continue;
        const double W = weight[static_cast<std::size_t>(r)];
        const auto row = static_cast<int>(kept_rhs.size());
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(all, r); it; ++it)
            kept.emplace_back(row, static_cast<int>(it.col()), it.value() / W);
        kept_rhs.push_back(rhs[static_cast<std::size_t>(r)] / W);
    }
    LinearVelocityRows rows;
    rows.B.resize(static_cast<Eigen::Index>(kept_rhs.size()), map.variables());
    rows.B.setFromTriplets(kept.begin(), kept.end());
    rows.rhs = Eigen::Map<const Eigen::VectorXd>(kept_rhs.data(), static_cast<Eigen::Index>(kept_rhs.size()));
    return rows;
}

template LinearVelocityRows inextensibility_rows<2>(const Particles<2>&, const GridVelocityMap<2>&, double,
                                                    const InextensibilitySettings&);
template LinearVelocityRows inextensibility_rows<3>(const Particles<3>&, const GridVelocityMap<3>&, double,
                                                    const InextensibilitySettings&);

} // namespace sinew
