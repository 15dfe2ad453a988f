#include "sinew/mpm/damage/particle_driving_forces.hpp"

#include "sinew/mpm/damage/driving_force.hpp"

#include <Eigen/LU>

#include <sstream>
#include <stdexcept>

namespace sinew {

template <int Dim>
std::string update_driving_forces(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                  std::vector<double>& driving)
{
    const auto count = static_cast<std::size_t>(particles.size());
    if (particles.phase_field.size() != count)
        throw std::invalid_argument("update_driving_forces: the particles carry no phase-field points");
    std::vector<double> current(count);
    for (std::size_t p = 0; p < count; ++p) {
        const auto& model = *models[static_cast<std::size_t>(particles.material[p])];
        const auto force = driving_force(model, particles.F[p], particles.point[p], particles.phase_field[p]);
        if (!force) {
            std::ostringstream failure;
            failure << "particle " << p << ": the undegraded stress of the damage's driving force is not defined at det F = "
                    << particles.F[p].determinant();
            return failure.str();
        }
        current[p] = force->current;
    }
    driving.resize(count);
    for (std::size_t p = 0; p < count; ++p) {
        double& history = particles.phase_field[p].history;
        driving[p] = driving_force_with_history(current[p], history);  // D̃ = max(ζ⟨Φ − 1⟩, D̃ᴴ)
        history = driving[p];
    }
    return {};
}

template <int Dim>
std::string start_damage_update(Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                                std::vector<double>& driving, DamageGrid<Dim>& grid)
{
    std::string failure = update_driving_forces(particles, models, driving);
    if (failure.empty())
        damage_to_grid(particles, grid);
    return failure;
}

template std::string update_driving_forces<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&,
                                              std::vector<double>&);
template std::string update_driving_forces<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&,
                                              std::vector<double>&);

template std::string start_damage_update<2>(Particles<2>&, const std::vector<const ConstitutiveModel<2, 2>*>&,
                                            std::vector<double>&, DamageGrid<2>&);
template std::string start_damage_update<3>(Particles<3>&, const std::vector<const ConstitutiveModel<3, 3>*>&,
                                            std::vector<double>&, DamageGrid<3>&);

} // namespace sinew
