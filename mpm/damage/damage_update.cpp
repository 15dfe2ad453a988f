#include "sinew/mpm/damage/damage_update.hpp"

#include "sinew/mpm/damage/explicit_damage.hpp"

#include <algorithm>
#include <limits>

namespace sinew {

template <int Dim>
DamageReport update_damage(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                           double dt, const DamageSettings& settings, DamageGrid<Dim>& grid,
                           const SpdSolve& solve)
{
    if (settings.integration == DamageIntegration::explicit_damage)
        return explicit_damage(particles, models, dt, grid);
    return implicit_damage(particles, models, dt, settings.implicit, grid, solve);
}

template <int Dim>
double explicit_damage_time_step(const Particles<Dim>& particles, double dx)
{
    double bound = std::numeric_limits<double>::infinity();
    for (const PhaseFieldPoint<Dim>& field : particles.phase_field) {
        const double rho = 4.0 * Dim / (dx * dx);  // ρ(Δ_h) ≤ 4 Dim/dx²
        bound = std::min(bound, 2.0 * field.eta / (1.0 + field.l0 * field.l0 * rho));
    }
    return bound;
}

template DamageReport update_damage<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&, double,
                                       const DamageSettings&, DamageGrid<2>&, const SpdSolve&);
template DamageReport update_damage<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&, double,
                                       const DamageSettings&, DamageGrid<3>&, const SpdSolve&);
template double explicit_damage_time_step<2>(const Particles<2>&, double);
template double explicit_damage_time_step<3>(const Particles<3>&, double);

} // namespace sinew
