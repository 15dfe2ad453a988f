#include "sinew/mpm/explicit_step.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/particle_buckets.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

namespace sinew {
namespace {

/// P of every particle, runs of one material evaluated together
/// (evaluate_batch: the 3×3 models fill SIMD lanes), in parallel. Empty when
/// every ψ and P is finite, else the lowest particle whose is not.
template <int Dim>
std::string particle_stresses(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                              std::vector<typename Particles<Dim>::Matrix>& stress)
{
    constexpr int kRun = 64;  // particles a call
    const int count = particles.size();
    stress.resize(static_cast<std::size_t>(count));
    std::vector<double> psi(static_cast<std::size_t>(count));
    const int runs = (count + kRun - 1) / kRun;
#pragma omp parallel for schedule(dynamic, 4)
    for (int run = 0; run < runs; ++run) {
        for (int first = run * kRun, end = std::min(count, first + kRun); first < end;) {
            const int material = particles.material[static_cast<std::size_t>(first)];
            int last = first + 1;
            while (last < end && particles.material[static_cast<std::size_t>(last)] == material)
                ++last;
            const auto f = static_cast<std::size_t>(first);
            models[static_cast<std::size_t>(material)]->evaluate_batch(last - first, &particles.F[f], &particles.point[f],
                                                                        &psi[f], &stress[f], nullptr, Projection::none);
            first = last;
        }
    }
    for (int p = 0; p < count; ++p)
        if (!std::isfinite(psi[static_cast<std::size_t>(p)]) || !stress[static_cast<std::size_t>(p)].allFinite()) {
            std::ostringstream failure;
            failure << "particle " << p << ": the stress is not finite at det F = "
                    << particles.F[static_cast<std::size_t>(p)].determinant();
            return failure.str();
        }
    return {};
}

/// Adds the MLS stress divergence times Δt to the grid's momentum,
/// (m v)_i += Δt f_i, bucket by bucket (particle_buckets.hpp). Empty when
/// every stress was finite, else which was not.
template <int Dim>
std::string add_stress_impulses(const Particles<Dim>& particles,
                                const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid)
{
    using Matrix = typename Particles<Dim>::Matrix;
    using Bucket = typename ParticleBuckets<Dim>::Bucket;
    std::vector<Matrix> stress;
    const std::string failure = particle_stresses(particles, models, stress);
    if (!failure.empty())
        return failure;
    const double dx = grid.dx();
    const double inverse_D = 1.0 / (apic_inertia_factor(settings.transfer.order) * dx * dx);
    const ParticleBuckets<Dim> buckets = bucket_particles(particles, settings.transfer.order, grid);
    for_each_bucket_by_colour(buckets, [&](const Bucket& bucket) {
        for (int j = bucket.first; j < bucket.last; ++j) {
            const auto i = static_cast<std::size_t>(buckets.order[static_cast<std::size_t>(j)]);
            // −Δt V_p⁰ P Fᵀ D⁻¹: the particle's impulse per unit of w_ip (x_i − x_p)
            const Matrix impulse =
                -settings.time_step * particles.volume[i] * inverse_D * stress[i] * particles.F[i].transpose();
            const BSplineStencil<Dim> stencil = bspline_weights<Dim>(particles.x[i], dx, settings.transfer.order);
            for_each_stencil_node<Dim>(bucket, stencil, particles.x[i], dx,
                                       [&](int slot, double w, const typename Particles<Dim>::Vector& d) {
                                           grid.momentum[static_cast<std::size_t>(slot)] += w * impulse * d;
                                       });
        }
    });
    return {};
}

/// v_i = (m v)_i / m_i + Δt g where m_i > 0.
template <int Dim>
void update_grid_velocity(const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid)
{
    const int slots = grid.slots();
#pragma omp parallel for schedule(static)
    for (int slot = 0; slot < slots; ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        if (grid.mass[s] > 0.0)
            grid.velocity[s] = grid.momentum[s] / grid.mass[s] + settings.time_step * settings.gravity;
    }
}

} // namespace

template <int Dim>
ExplicitStepReport explicit_step(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                 const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid)
{
    for (int p = 0; p < particles.size(); ++p) {
        const int material = particles.material[static_cast<std::size_t>(p)];
        if (material < 0 || material >= static_cast<int>(models.size()) || !models[static_cast<std::size_t>(material)])
            throw InputError("particle " + std::to_string(p) + " has material " + std::to_string(material) +
                             ", which has no model (" + std::to_string(models.size()) + " given)");
    }
    ExplicitStepReport report;
    auto clock = std::chrono::steady_clock::now();
    auto lap = [&clock] {
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - clock).count();
        clock = now;
        return seconds;
    };
    particles_to_grid(particles, settings.transfer, grid);
    report.to_grid_s = lap();
    report.failure = add_stress_impulses(particles, models, settings, grid);
    report.stress_s = lap();
    if (!report.failure.empty())
        return report;
    update_grid_velocity(settings, grid);
    apply_grid_conditions(settings, grid);
    report.grid_update_s = lap();
    advect_particles(settings, grid, particles);
    report.to_particles_s = lap();
    return report;
}

template ExplicitStepReport explicit_step<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&,
                                             const MpmStepSettings<2>&, SparseGrid<2>&);
template ExplicitStepReport explicit_step<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&,
                                             const MpmStepSettings<3>&, SparseGrid<3>&);

} // namespace sinew
