#include "sinew/mpm/transfers.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/particle_buckets.hpp"

#include <cmath>
#include <sstream>

namespace sinew {

template <int Dim>
void check_in_grid(const Particles<Dim>& particles, int p, double dx)
{
    const auto& x = particles.x[static_cast<std::size_t>(p)];
    const double reach = static_cast<double>(SparseGrid<Dim>::kMaxIndex - 4) * dx;
    if (!x.allFinite() || x.cwiseAbs().maxCoeff() >= reach) {
        std::ostringstream message;
        message << "particle " << p << " at (" << x.transpose() << ") lies outside the grid's domain, |x| < "
                << reach << " in each axis (2^20 cells of dx = " << dx << ")";
        throw InputError(message.str());
    }
}

template <int Dim>
BSplineStencil<Dim> checked_stencil(const Particles<Dim>& particles, int p, double dx, SplineOrder order)
{
    check_in_grid(particles, p, dx);
    return bspline_stencil<Dim>(particles.x[static_cast<std::size_t>(p)], dx, order);
}

template <int Dim>
void particles_to_grid(const Particles<Dim>& particles, const TransferSettings& settings, SparseGrid<Dim>& grid)
{
    using Vector = typename SparseGrid<Dim>::Vector;
    using Bucket = typename ParticleBuckets<Dim>::Bucket;
    grid.clear();
    touch_stencil_blocks(particles, settings.order, grid);
    const ParticleBuckets<Dim> buckets = bucket_particles(particles, settings.order, grid);
    const double dx = grid.dx();
    const bool affine = settings.scheme == TransferScheme::apic;
    for_each_bucket_by_colour(buckets, [&](const Bucket& bucket) {
        for (int j = bucket.first; j < bucket.last; ++j) {
            const auto i = static_cast<std::size_t>(buckets.order[static_cast<std::size_t>(j)]);
            const BSplineStencil<Dim> stencil = bspline_weights<Dim>(particles.x[i], dx, settings.order);
            const double m = particles.mass[i];
            const Vector v_p = particles.v[i];
            const typename Particles<Dim>::Matrix C_p = affine ? particles.C[i] : Particles<Dim>::Matrix::Zero();
            for_each_stencil_node<Dim>(bucket, stencil, particles.x[i], dx, [&](int slot, double w, const Vector& d) {
                const auto s = static_cast<std::size_t>(slot);
                grid.mass[s] += w * m;
                grid.momentum[s] += w * m * (v_p + C_p * d);  // v_p + C_p (x_i − x_p)
            });
        }
    });
    const int slots = grid.slots();
#pragma omp parallel for schedule(static)
    for (int slot = 0; slot < slots; ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        grid.velocity[s] = grid.mass[s] > 0.0 ? Vector(grid.momentum[s] / grid.mass[s]) : Vector::Zero();
        grid.velocity_transferred[s] = grid.velocity[s];
    }
}

template <int Dim>
void grid_to_particles(const SparseGrid<Dim>& grid, const TransferSettings& settings, Particles<Dim>& particles)
{
    using Vector = typename SparseGrid<Dim>::Vector;
    using Matrix = typename Particles<Dim>::Matrix;
    using Bucket = typename ParticleBuckets<Dim>::Bucket;
    const double dx = grid.dx();
    const double inverse_D = 1.0 / (apic_inertia_factor(settings.order) * dx * dx);  // D_p⁻¹ = I/(σ dx²)
    const bool flip = settings.scheme == TransferScheme::pic_flip;
    const ParticleBuckets<Dim> buckets = bucket_particles(particles, settings.order, grid);
    for_each_bucket(buckets, [&](const Bucket& bucket) {
        for (int j = bucket.first; j < bucket.last; ++j) {
            const auto i = static_cast<std::size_t>(buckets.order[static_cast<std::size_t>(j)]);
            const BSplineStencil<Dim> stencil = bspline_weights<Dim>(particles.x[i], dx, settings.order);
            Vector v_pic = Vector::Zero(), increment = Vector::Zero();
            Matrix B = Matrix::Zero();
            for_each_stencil_node<Dim>(bucket, stencil, particles.x[i], dx, [&](int slot, double w, const Vector& d) {
                const auto s = static_cast<std::size_t>(slot);
                v_pic += w * grid.velocity[s];
                if (flip)
                    increment += w * (grid.velocity[s] - grid.velocity_transferred[s]);
                B += w * grid.velocity[s] * d.transpose();
            });
            particles.C[i] = B * inverse_D;
            particles.v[i] = flip ? Vector((1.0 - settings.flip_ratio) * v_pic +
                                           settings.flip_ratio * (particles.v[i] + increment))
                                  : v_pic;
        }
    });
}

template void check_in_grid<2>(const Particles<2>&, int, double);
template void check_in_grid<3>(const Particles<3>&, int, double);
template BSplineStencil<2> checked_stencil<2>(const Particles<2>&, int, double, SplineOrder);
template BSplineStencil<3> checked_stencil<3>(const Particles<3>&, int, double, SplineOrder);
template void particles_to_grid<2>(const Particles<2>&, const TransferSettings&, SparseGrid<2>&);
template void particles_to_grid<3>(const Particles<3>&, const TransferSettings&, SparseGrid<3>&);
template void grid_to_particles<2>(const SparseGrid<2>&, const TransferSettings&, Particles<2>&);
template void grid_to_particles<3>(const SparseGrid<3>&, const TransferSettings&, Particles<3>&);

} // namespace sinew
