#include "sinew/mpm/damage/explicit_damage.hpp"

#include "sinew/mpm/damage/particle_driving_forces.hpp"

#include <algorithm>

namespace sinew {

template <int Dim>
DamageReport explicit_damage(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                             double dt, DamageGrid<Dim>& grid)
{
    DamageReport report;
    std::vector<double> driving;
    report.failure = start_damage_update(particles, models, driving, grid);
    if (!report.failure.empty())
        return report;
    const std::vector<double> laplacian = damage_laplacians(particles, grid);
    for (std::size_t p = 0; p < particles.point.size(); ++p) {
        const PhaseFieldPoint<Dim>& field = particles.phase_field[p];
        double& d = particles.point[p].damage;
        const double resistance = d - field.l0 * field.l0 * laplacian[p];  // D_c = d − l₀²Δd
        const double rate = (1.0 - d) * driving[p] - resistance;          // (1 − d)D̃ − D_c
        if (!(rate > 0.0))
            continue;
        const double raised = d + dt / field.eta * rate;
        report.capped_at_one += raised > 1.0 ? 1 : 0;
        const double next = std::min(1.0, raised);
        report.grown += next > d ? 1 : 0;
        d = next;
    }
    return report;
}

template DamageReport explicit_damage<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&, double,
                                         DamageGrid<2>&);
template DamageReport explicit_damage<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&, double,
                                         DamageGrid<3>&);

} // namespace sinew
