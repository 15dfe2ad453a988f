#pragma once
#include "sinew/mpm/sparse_grid.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace sinew {

/// What a wall or a collider does to the grid velocity of a node it holds.
enum class GridCondition {
    sticky,   ///< v = v_b, the obstacle's velocity
    slip,     ///< the normal part of v − v_b removed
    separate  ///< the normal part of v − v_b removed only when it points into the obstacle
};

/// One wall or collider holding one node: its condition, the obstacle's
/// velocity v_b and the unit normal n out of the obstacle at the node (zero
/// where the obstacle has none, a ball's centre: the node is then held at v_b).
template <int Dim>
struct NodeContact {
    GridCondition condition = GridCondition::sticky;
    Eigen::Matrix<double, Dim, 1> velocity = Eigen::Matrix<double, Dim, 1>::Zero();
    Eigen::Matrix<double, Dim, 1> normal = Eigen::Matrix<double, Dim, 1>::Zero();
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

/// v after each contact's condition in turn (conditioned_velocity; held at
/// v_b where the normal is zero).
template <int Dim>
Eigen::Matrix<double, Dim, 1> conditioned_velocity(const std::vector<NodeContact<Dim>>& contacts,
                                                   Eigen::Matrix<double, Dim, 1> v)
{
    for (const NodeContact<Dim>& contact : contacts)
        v = contact.normal.squaredNorm() > 0.0
                ? conditioned_velocity<Dim>(contact.condition, v, contact.velocity, contact.normal)
                : contact.velocity;
    return v;
}

/// Every node of `grid` with mass takes the conditions of contacts_at(x_i)
/// in turn: the one loop walls, colliders and a step's conditions share.
template <int Dim, typename ContactsAt>
void apply_node_contacts(SparseGrid<Dim>& grid, const ContactsAt& contacts_at)
{
    for (int slot = 0; slot < grid.slots(); ++slot) {
        const auto s = static_cast<std::size_t>(slot);
        if (grid.mass[s] > 0.0)
            grid.velocity[s] = conditioned_velocity<Dim>(contacts_at(grid.position(slot)), grid.velocity[s]);
    }
}

} // namespace sinew
