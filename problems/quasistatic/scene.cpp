#include "sinew/problems/quasistatic/scene.hpp"

#include <Eigen/Geometry>

namespace sinew {

Eigen::MatrixXd PrescribedMotion::map_at(double s, int dimension) const
{
    const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(dimension, dimension);
    if (!rotation)
        return identity + s * (map - identity);
    if (dimension == 2)
        return Eigen::Rotation2Dd(s * angle).toRotationMatrix();
    return Eigen::AngleAxisd(s * angle, axis).toRotationMatrix();
}

Eigen::VectorXd PrescribedMotion::translation_at(double s, int dimension) const
{
    if (!rotation)
        return s * translation;
    // x = R(sθ)(X − c) + c + s·t = R X + (c − R c + s·t)
    return center - map_at(s, dimension) * center + s * translation;
}

void Scene::apply_load_factor(double s) { apply_load_factors(s, s, 1.0); }

void Scene::apply_load_factors(double s0, double s1, double w)
{
    const int dimension = problem->potential().dimension();
    for (size_t k = 0; k < motions.size(); ++k) {
        const PrescribedMotion& m = motions[k];
        problem->set_affine_map(static_cast<int>(k),
                                (1.0 - w) * m.map_at(s0, dimension) + w * m.map_at(s1, dimension),
                                (1.0 - w) * m.translation_at(s0, dimension) + w * m.translation_at(s1, dimension));
    }
    const double s = (1.0 - w) * s0 + w * s1;  // the quantities linear in s
    if (gravity)
        gravity->set_scale(s);
    if (loads)
        loads->set_scale(s);
    for (int e = 0; e < elastic->num_elements(); ++e)
        elastic->set_activation(e, s * target_activations[e]);
}

Eigen::VectorXd Scene::fixed_flags() const
{
    Eigen::VectorXd flags = Eigen::VectorXd::Zero(mesh.num_nodes());
    for (const auto& set : problem->dirichlet_sets())
        for (int node : set.nodes)
            flags[node] = 1.0;
    return flags;
}

} // namespace sinew
