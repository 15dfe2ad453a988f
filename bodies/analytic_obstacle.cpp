#include "sinew/energies/potentials/analytic_obstacle.hpp"

namespace sinew {

std::string obstacle_kind(const AnalyticObstacle& obstacle)
{
    return std::holds_alternative<PlaneObstacle>(obstacle) ? "plane" : "sphere";
}

} // namespace sinew
