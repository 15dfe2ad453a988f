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

void Scene::apply_load_factor(double s)
{
    for (const ScaledQuantity& q : scaled)
        q.set(*this, s, s, 1.0);
}

void Scene::apply_time(double t) { apply_time(t, t, 1.0); }

void Scene::apply_time(double t0, double t1, double w)
{
    const KeyframeCurve constant(1.0);
    const KeyframeCurve& load_curve = dynamics ? dynamics->load_factor : constant;
    for (const ScaledQuantity& q : scaled) {
        const KeyframeCurve& s = q.curve ? *q.curve : load_curve;
        q.set(*this, s.at(t0), s.at(t1), w);
    }
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
