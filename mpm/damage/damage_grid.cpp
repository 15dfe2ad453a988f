#include "sinew/mpm/damage/damage_grid.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/bspline_stencil.hpp"

#include <string>

namespace sinew {

template <int Dim>
void damage_to_grid(const Particles<Dim>& particles, DamageGrid<Dim>& grid)
{
    using Index = typename BSplineStencil<Dim>::Index;
    grid.nodes.clear();
    for (int p = 0; p < particles.size(); ++p) {
        const auto& x = particles.x[static_cast<std::size_t>(p)];
        const Index base = stencil_base<Dim>(x, grid.nodes.dx(), SplineOrder::cubic);
        const Index last = base + Index::Constant(stencil_width(SplineOrder::cubic) - 1);
        if (!x.allFinite() || !SparseGrid<Dim>::holds(base) || !SparseGrid<Dim>::holds(last))
            throw InputError("damage grid: particle " + std::to_string(p) + " lies outside the grid's range");
        BSplineStencil<Dim> corners;
        corners.width = stencil_width(SplineOrder::cubic);
        corners.for_each_offset([&](const Index& offset) { grid.nodes.touch(base + offset); });
    }
    const auto slots = static_cast<std::size_t>(grid.nodes.slots());
    grid.weight.assign(slots, 0.0);
    grid.damage.assign(slots, 0.0);
    for (int p = 0; p < particles.size(); ++p) {
        const double d = particles.point[static_cast<std::size_t>(p)].damage;
        for_each_damage_node(particles, grid, p, [&](int slot, double w, const auto&) {
            grid.weight[static_cast<std::size_t>(slot)] += w;
            grid.damage[static_cast<std::size_t>(slot)] += w * d;
        });
    }
    for (std::size_t i = 0; i < slots; ++i)
        if (grid.weight[i] > 0.0)
            grid.damage[i] /= grid.weight[i];  // d_i = Σ w d_p / Σ w
}

template <int Dim>
std::vector<double> damage_laplacians(const Particles<Dim>& particles, const DamageGrid<Dim>& grid)
{
    using Index = typename BSplineStencil<Dim>::Index;
    std::vector<double> laplacian(static_cast<std::size_t>(particles.size()), 0.0);
    for (int p = 0; p < particles.size(); ++p) {
        const BSplineStencil<Dim> stencil =
            bspline_stencil<Dim>(particles.x[static_cast<std::size_t>(p)], grid.nodes.dx(), SplineOrder::cubic);
        double sum = 0.0;
        stencil.for_each_offset([&](const Index& offset) {
            const int slot = grid.nodes.find(stencil.base + offset);
            sum += grid.damage[static_cast<std::size_t>(slot)] * stencil.laplacian(offset);  // d_i ΔN_i
        });
        laplacian[static_cast<std::size_t>(p)] = sum;
    }
    return laplacian;
}

template void damage_to_grid<2>(const Particles<2>&, DamageGrid<2>&);
template void damage_to_grid<3>(const Particles<3>&, DamageGrid<3>&);
template std::vector<double> damage_laplacians<2>(const Particles<2>&, const DamageGrid<2>&);
template std::vector<double> damage_laplacians<3>(const Particles<3>&, const DamageGrid<3>&);

} // namespace sinew
