#include "sinew/mpm/transfers.hpp"

#include "sinew/core/input_error.hpp"

#include <cmath>
#include <sstream>

namespace sinew {

template <int Dim>
BSplineStencil<Dim> checked_stencil(const Particles<Dim>& particles, int p, double dx, SplineOrder order)
{
    const auto& x = particles.x[static_cast<std::size_t>(p)];
    const double reach = static_cast<double>(SparseGrid<Dim>::kMaxIndex - 4) * dx;
    if (!x.allFinite() || x.cwiseAbs().maxCoeff() >= reach) {
        std::ostringstream message;
        message << "particle " << p << " at (" << x.transpose() << ") lies outside the grid's domain, |x| < "
                << reach << " in each axis (2^20 cells of dx = " << dx << ")";
        throw InputError(message.str());
    }
    return bspline_stencil<Dim>(x, dx, order);
}

template <int Dim>
void particles_to_grid(const Particles<Dim>& particles, const TransferSettings& settings, SparseGrid<Dim>& grid)
{
    using Index = typename SparseGrid<Dim>::Index;
    using Vector = typename SparseGrid<Dim>::Vector;
    grid.clear();
    const double dx = grid.dx();
    const bool affine = settings.scheme == TransferScheme::apic;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const BSplineStencil<Dim> stencil = checked_stencil(particles, p, dx, settings.order);
        const double m = particles.mass[i];
        stencil.for_each_offset([&](const Index& offset) {
            const Index node = stencil.base + offset;
            const double w = stencil.weight(offset);
            const int slot = grid.touch(node);
            Vector v = particles.v[i];
            if (affine)
                v += particles.C[i] * (node.template cast<double>() * dx - particles.x[i]);  // v_p + C_p (x_i − x_p)
            grid.mass[static_cast<std::size_t>(slot)] += w * m;
            grid.momentum[static_cast<std::size_t>(slot)] += w * m * v;
        });
    }
    for (int slot = 0; slot < grid.slots(); ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        grid.velocity[s] = grid.mass[s] > 0.0 ? Vector(grid.momentum[s] / grid.mass[s]) : Vector::Zero();
        grid.velocity_transferred[s] = grid.velocity[s];
    }
}

template <int Dim>
void grid_to_particles(const SparseGrid<Dim>& grid, const TransferSettings& settings, Particles<Dim>& particles)
{
    using Index = typename SparseGrid<Dim>::Index;
    using Vector = typename SparseGrid<Dim>::Vector;
    using Matrix = typename Particles<Dim>::Matrix;
    const double dx = grid.dx();
    const double inverse_D = 1.0 / (apic_inertia_factor(settings.order) * dx * dx);  // D_p⁻¹ = I/(σ dx²)
    const bool flip = settings.scheme == TransferScheme::pic_flip;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const BSplineStencil<Dim> stencil = checked_stencil(particles, p, dx, settings.order);
        Vector v_pic = Vector::Zero(), increment = Vector::Zero();
        Matrix B = Matrix::Zero();
        stencil.for_each_offset([&](const Index& offset) {
            const Index node = stencil.base + offset;
            const int slot = grid.find(node);
            if (slot < 0)
                return;  // a node no particle reached: zero weight from this particle too
            const auto s = static_cast<std::size_t>(slot);
            const double w = stencil.weight(offset);
            v_pic += w * grid.velocity[s];
            increment += w * (grid.velocity[s] - grid.velocity_transferred[s]);
            B += w * grid.velocity[s] * (node.template cast<double>() * dx - particles.x[i]).transpose();
        });
        particles.C[i] = B * inverse_D;
        particles.v[i] = flip ? Vector((1.0 - settings.flip_ratio) * v_pic +
                                       settings.flip_ratio * (particles.v[i] + increment))
                              : v_pic;
    }
}

template BSplineStencil<2> checked_stencil<2>(const Particles<2>&, int, double, SplineOrder);
template BSplineStencil<3> checked_stencil<3>(const Particles<3>&, int, double, SplineOrder);
template void particles_to_grid<2>(const Particles<2>&, const TransferSettings&, SparseGrid<2>&);
template void particles_to_grid<3>(const Particles<3>&, const TransferSettings&, SparseGrid<3>&);
template void grid_to_particles<2>(const SparseGrid<2>&, const TransferSettings&, Particles<2>&);
template void grid_to_particles<3>(const SparseGrid<3>&, const TransferSettings&, Particles<3>&);

} // namespace sinew
