#pragma once
#include <Eigen/Core>

#include <string>

namespace sinew {

/// What a wall or a collider does to the grid velocity of a node it holds.
enum class GridCondition {
    sticky,   ///< v = v_b, the obstacle's velocity
    slip,     ///< the normal part of v − v_b removed
    separate  ///< the normal part of v − v_b removed only when it points into the obstacle
};

/// "sticky", "slip", "separate"; InputError naming the choices otherwise.
GridCondition grid_condition(const std::string& name);

/// v after `condition` against an obstacle moving at v_b whose surface has
/// the unit normal n, pointing out of the obstacle:
///   sticky v_b;  slip v_b + r − (r·n) n;  separate the same when r·n < 0, else v,
/// with r = v − v_b.
template <int Dim>
Eigen::Matrix<double, Dim, 1> conditioned_velocity(GridCondition condition, const Eigen::Matrix<double, Dim, 1>& v,
                                                   const Eigen::Matrix<double, Dim, 1>& v_b,
                                                   const Eigen::Matrix<double, Dim, 1>& n)
{
    const Eigen::Matrix<double, Dim, 1> r = v - v_b;  // relative velocity
    const double approach = r.dot(n);                  // < 0: moving into the obstacle
    switch (condition) {
    case GridCondition::sticky: return v_b;
    case GridCondition::slip: return v_b + r - approach * n;
    case GridCondition::separate: return approach < 0.0 ? Eigen::Matrix<double, Dim, 1>(v_b + r - approach * n) : v;
    }
    return v;
}

} // namespace sinew
