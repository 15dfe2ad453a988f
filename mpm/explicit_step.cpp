#include "sinew/mpm/explicit_step.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mpm/transfers.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

namespace sinew {
namespace {

/// The stress impulse of every particle, S_p = −Δt V_p⁰ D_p⁻¹ P(F_p) F_pᵀ,
/// its momentum per unit of w_ip (x_i − x_p) (the MLS stress divergence,
/// f_i = Σ_p S_p (x_i − x_p) w_ip / Δt), scattered with the particles'
/// momentum. P in runs of one material (evaluate_batch: the 3×3 models fill
/// SIMD lanes), in parallel. Empty when every ψ and P is finite, else the
/// lowest particle whose is not.
template <int Dim>
std::string stress_impulses(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                            const MpmStepSettings<Dim>& settings, double dx,
                            std::vector<typename Particles<Dim>::Matrix>& impulse, std::vector<double>& psi)
{
    constexpr int kRun = 64;  // particles a call
    const int count = particles.size();
    impulse.resize(static_cast<std::size_t>(count));
    psi.resize(static_cast<std::size_t>(count));
    const double inverse_D = 1.0 / (apic_inertia_factor(settings.transfer.order) * dx * dx);
    const int runs = (count + kRun - 1) / kRun;
#pragma omp parallel for schedule(dynamic, 4)
    for (int run = 0; run < runs; ++run) {
        const int run_end = std::min(count, (run + 1) * kRun);
        for (int first = run * kRun; first < run_end;) {
            const int material = particles.material[static_cast<std::size_t>(first)];
            int last = first + 1;
            while (last < run_end && particles.material[static_cast<std::size_t>(last)] == material)
                ++last;
            const auto f = static_cast<std::size_t>(first);
            models[static_cast<std::size_t>(material)]->evaluate_batch(last - first, &particles.F[f], &particles.point[f],
                                                                        &psi[f], &impulse[f], nullptr, Projection::none);
            first = last;
        }
        for (int p = run * kRun; p < run_end; ++p) {
            const auto i = static_cast<std::size_t>(p);
            impulse[i] = (-settings.time_step * particles.volume[i] * inverse_D) * impulse[i] * particles.F[i].transpose();
        }
    }
    int first_failed = count;
#pragma omp parallel for schedule(static) reduction(min : first_failed)
    for (int p = 0; p < count; ++p)
        if (!std::isfinite(psi[static_cast<std::size_t>(p)]) || !impulse[static_cast<std::size_t>(p)].allFinite())
            first_failed = std::min(first_failed, p);
    if (first_failed == count)
        return {};
    std::ostringstream failure;
    failure << "particle " << first_failed << ": the stress is not finite at det F = "
            << particles.F[static_cast<std::size_t>(first_failed)].determinant();
    return failure.str();
}

/// v_i ← v_i + Δt g where m_i > 0.
template <int Dim>
void add_gravity(const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid)
{
    const int slots = grid.slots();
#pragma omp parallel for schedule(static)
    for (int slot = 0; slot < slots; ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        if (grid.mass[s] > 0.0)
            grid.velocity[s] += settings.time_step * settings.gravity;
    }
}

} // namespace

template <int Dim>
ExplicitStepReport explicit_step(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                 const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid,
                                 const GridInextensibility<Dim>* inextensibility)
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
    std::vector<typename Particles<Dim>::Matrix>& impulses = grid.buffers.impulse;
    report.failure = stress_impulses(particles, models, settings, grid.dx(), impulses, grid.buffers.energy);
    report.stress_s = lap();
    if (!report.failure.empty())
        return report;
    const ParticleBuckets<Dim> layout = particles_to_grid(particles, settings.transfer, grid, &impulses);
    report.to_grid_s = lap();
    add_gravity(settings, grid);
    if (inextensibility)
        report.inextensibility = project_grid_velocities(particles, settings, *inextensibility, grid);
    apply_grid_conditions(settings, grid);
    report.grid_update_s = lap() - report.inextensibility.seconds;
    advect_particles(settings, grid, layout, particles);
    report.to_particles_s = lap();
    return report;
}

template ExplicitStepReport explicit_step<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&,
                                             const MpmStepSettings<2>&, SparseGrid<2>&,
                                             const GridInextensibility<2>*);
template ExplicitStepReport explicit_step<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&,
                                             const MpmStepSettings<3>&, SparseGrid<3>&,
                                             const GridInextensibility<3>*);

} // namespace sinew
