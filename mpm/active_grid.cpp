#include "sinew/mpm/active_grid.hpp"

namespace sinew {

template <int Dim>
ActiveGrid<Dim> active_grid(const SparseGrid<Dim>& grid)
{
    using Index = typename SparseGrid<Dim>::Index;
    ActiveGrid<Dim> out;
    std::vector<int> point_of_slot(static_cast<std::size_t>(grid.slots()), -1);
    for (int slot = 0; slot < grid.slots(); ++slot)
        if (grid.mass[static_cast<std::size_t>(slot)] > 0.0) {
            point_of_slot[static_cast<std::size_t>(slot)] = static_cast<int>(out.slots.size());
            out.slots.push_back(slot);
        }
    out.positions.resize(Dim, static_cast<Eigen::Index>(out.slots.size()));
    for (std::size_t k = 0; k < out.slots.size(); ++k)
        out.positions.col(static_cast<Eigen::Index>(k)) = grid.position(out.slots[k]);
    for (const int slot : out.slots) {
        const Index lower = grid.node(slot);
        std::array<int, (1 << Dim)> cell{};
        bool complete = true;
        for (int corner = 0; corner < (1 << Dim) && complete; ++corner) {
            Index node = lower;
            for (int a = 0; a < Dim; ++a)
                node[a] += (corner >> a) & 1;
            const int at = grid.find(node);
            cell[static_cast<std::size_t>(corner)] = at < 0 ? -1 : point_of_slot[static_cast<std::size_t>(at)];
            complete = cell[static_cast<std::size_t>(corner)] >= 0;
        }
        if (complete)
            out.cells.push_back(cell);
    }
    return out;
}

template ActiveGrid<2> active_grid<2>(const SparseGrid<2>&);
template ActiveGrid<3> active_grid<3>(const SparseGrid<3>&);

} // namespace sinew
