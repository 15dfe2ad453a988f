#pragma once
// Template bodies of damage_grid.hpp.
#include "sinew/mpm/bspline_stencil.hpp"

#include <stdexcept>

namespace sinew {

template <int Dim, typename Function>
void for_each_damage_node(const Particles<Dim>& particles, const DamageGrid<Dim>& grid, int p, Function&& f)
{
    const BSplineStencil<Dim> stencil =
        bspline_stencil<Dim>(particles.x[static_cast<std::size_t>(p)], grid.nodes.dx(), SplineOrder::cubic);
    stencil.for_each_offset([&](const typename BSplineStencil<Dim>::Index& offset) {
        const int slot = grid.nodes.find(stencil.base + offset);
        if (slot < 0)
            throw std::logic_error("for_each_damage_node: the damage grid does not hold the particle's stencil");
        f(slot, stencil.weight(offset), stencil.gradient(offset));
    });
}

} // namespace sinew
