#include "sinew/mpm/explicit_step.hpp"

#include <Eigen/LU>

#include <cmath>
#include <sstream>

namespace sinew {
namespace {

/// Adds the MLS stress divergence times Δt to the grid's momentum:
/// (m v)_i += Δt f_i. Empty when every stress was finite, else which was not.
template <int Dim>
std::string add_stress_impulses(const Particles<Dim>& particles,
                                const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid)
{
    using Index = typename SparseGrid<Dim>::Index;
    using Matrix = typename Particles<Dim>::Matrix;
    const double dx = grid.dx();
    const double inverse_D = 1.0 / (apic_inertia_factor(settings.transfer.order) * dx * dx);
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        const ConstitutiveModel<Dim, Dim>& model = *models.at(static_cast<std::size_t>(particles.material[i]));
        Matrix P;
        const double psi = model.evaluate(particles.F[i], particles.point[i], &P, nullptr, Projection::none);
        if (!std::isfinite(psi) || !P.allFinite()) {
            std::ostringstream failure;
            failure << "particle " << p << ": the stress is not finite at det F = " << particles.F[i].determinant();
            return failure.str();
        }
        // −Δt V_p⁰ P Fᵀ D⁻¹: the particle's impulse per unit of w_ip (x_i − x_p)
        const Matrix impulse = -settings.time_step * particles.volume[i] * inverse_D * P * particles.F[i].transpose();
        const BSplineStencil<Dim> stencil = checked_stencil(particles, p, dx, settings.transfer.order);
        stencil.for_each_offset([&](const Index& offset) {
            const Index node = stencil.base + offset;
            const auto slot = static_cast<std::size_t>(grid.find(node));
            grid.momentum[slot] += stencil.weight(offset) * impulse * (node.template cast<double>() * dx - particles.x[i]);
        });
    }
    return {};
}

/// v_i = (m v)_i / m_i + Δt g where m_i > 0.
template <int Dim>
void update_grid_velocity(const MpmStepSettings<Dim>& settings, SparseGrid<Dim>& grid)
{
    for (int slot = 0; slot < grid.slots(); ++slot) {
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
    ExplicitStepReport report;
    particles_to_grid(particles, settings.transfer, grid);
    report.failure = add_stress_impulses(particles, models, settings, grid);
    if (!report.failure.empty())
        return report;
    update_grid_velocity(settings, grid);
    finish_step(settings, grid, particles);
    return report;
}

template ExplicitStepReport explicit_step<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&,
                                             const MpmStepSettings<2>&, SparseGrid<2>&);
template ExplicitStepReport explicit_step<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&,
                                             const MpmStepSettings<3>&, SparseGrid<3>&);

} // namespace sinew
