#pragma once
#include <Eigen/Core>

#include <string>
#include <vector>

namespace sinew {

/// Nodes whose positions are prescribed by an affine map of their rest
/// positions, x_i = M X_i + t for every node i of the set: the form of the
/// cranium and jaw motions of seed 000 §2.2–2.3 (M and t from the rig
/// parameters θ_k; M need not be orthogonal), and of a homogeneous
/// deformation x = F̄ X on a boundary (the patch test). M = I, t = 0 holds the
/// nodes at rest.
struct DirichletSet {
    std::string name;             ///< for messages ("cranium", "jaw", …)
    std::vector<int> nodes;       ///< node indices, each at most once
    Eigen::MatrixXd map;          ///< M, dimension × dimension
    Eigen::VectorXd translation;  ///< t, dimension (m)
};

/// A set held at its rest positions (M = I, t = 0).
DirichletSet fixed_at_rest(std::string name, std::vector<int> nodes, int dimension);

/// "Dirichlet set 2 ('jaw')": how messages name set `index`.
std::string dirichlet_set_label(const DirichletSet& set, int index);

/// InputError naming the set and the offending node or entry unless M is
/// dimension × dimension, t has dimension entries, every entry of M and t is
/// finite, and every node is in [0, num_nodes) and listed once.
void check_dirichlet_set(const DirichletSet& set, int index, int dimension, int num_nodes);

} // namespace sinew
