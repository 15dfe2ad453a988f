#include "sinew/mpm/particle_sampling.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/element_geometry.hpp"

#include <cmath>
#include <string>

namespace sinew {
namespace {

template <int Dim>
void check_sampling(const LatticeSampling<Dim>& s, const std::string& what)
{
    if (!(std::isfinite(s.dx) && s.dx > 0.0))
        throw InputError(what + ": dx must be a positive number");
    if (s.per_cell < 1)
        throw InputError(what + ": particles_per_cell must be at least 1");
    if (!(std::isfinite(s.density) && s.density > 0.0))
        throw InputError(what + ": density must be a positive number");
    if (!s.velocity.allFinite())
        throw InputError(what + ": the velocity must be finite");
}

/// Particle counts along each axis of a lattice of spacing h over `extent`, checked against the limit.
template <int Dim>
Eigen::Matrix<long long, Dim, 1> lattice_counts(const Eigen::Matrix<double, Dim, 1>& extent, double h,
                                                 const std::string& what)
{
    Eigen::Matrix<long long, Dim, 1> n;
    double total = 1.0;
    for (int a = 0; a < Dim; ++a) {
        const double along = std::max(1.0, std::round(extent[a] / h));
        total *= along;
        if (total > kMaxSampledParticles)
            throw InputError(what + " would make more than 1e8 particles; use a larger dx or fewer particles_per_cell");
        n[a] = static_cast<long long>(along);
    }
    return n;
}

/// Calls f(i) for every multi-index 0 ≤ i < n, the last axis fastest.
template <int Dim, typename Function>
void for_each_lattice_point(const Eigen::Matrix<long long, Dim, 1>& n, Function&& f)
{
    Eigen::Matrix<long long, Dim, 1> i = Eigen::Matrix<long long, Dim, 1>::Zero();
    for (;;) {
        f(static_cast<const Eigen::Matrix<long long, Dim, 1>&>(i));
        int a = Dim - 1;
        while (a >= 0 && ++i[a] == n[a])
            i[a--] = 0;
        if (a < 0)
            return;
    }
}

} // namespace

template <int Dim>
Particles<Dim> sample_box(const Eigen::Matrix<double, Dim, 1>& lower, const Eigen::Matrix<double, Dim, 1>& upper,
                          const LatticeSampling<Dim>& sampling)
{
    check_sampling(sampling, "box");
    if (!lower.allFinite() || !upper.allFinite() || !((upper - lower).minCoeff() > 0.0))
        throw InputError("box: upper must exceed lower in every axis, both finite");
    const Eigen::Matrix<double, Dim, 1> extent = upper - lower;
    const auto n = lattice_counts<Dim>(extent, sampling.dx / sampling.per_cell, "box");
    const Eigen::Matrix<double, Dim, 1> spacing = extent.cwiseQuotient(n.template cast<double>());
    const double volume = spacing.prod();
    Particles<Dim> particles;
    for_each_lattice_point<Dim>(n, [&](const Eigen::Matrix<long long, Dim, 1>& i) {
        const Eigen::Matrix<double, Dim, 1> x =
            lower + (i.template cast<double>() + Eigen::Matrix<double, Dim, 1>::Constant(0.5)).cwiseProduct(spacing);
        particles.add(x, sampling.velocity, sampling.density * volume, volume, sampling.material);
    });
    return particles;
}

template <int Dim>
Particles<Dim> sample_inside(const CollisionBody& body, const Eigen::Matrix<double, Dim, 1>& lower,
                             const Eigen::Matrix<double, Dim, 1>& upper, const LatticeSampling<Dim>& sampling)
{
    using Vector = Eigen::Matrix<double, Dim, 1>;
    check_sampling(sampling, "inside " + body.name());
    if (body.dimension() != Dim)
        throw InputError("inside " + body.name() + ": a " + std::to_string(body.dimension()) + "D body in a " +
                         std::to_string(Dim) + "D scene");
    if (!lower.allFinite() || !upper.allFinite() || !(lower.array() < upper.array()).all())
        throw InputError("inside " + body.name() + ": its bounding box is empty or not finite");
    const double h = sampling.dx / sampling.per_cell;
    // Lattice indices k with (k + ½) h in [lower, upper]
    Eigen::Matrix<long long, Dim, 1> first;
    Vector extent;
    for (int a = 0; a < Dim; ++a) {
        first[a] = static_cast<long long>(std::floor(lower[a] / h));
        extent[a] = (std::ceil(upper[a] / h) - static_cast<double>(first[a])) * h;
    }
    const auto n = lattice_counts<Dim>(extent, h, "inside " + body.name());
    const double volume = std::pow(h, Dim);
    Particles<Dim> particles;
    for_each_lattice_point<Dim>(n, [&](const Eigen::Matrix<long long, Dim, 1>& i) {
        const Vector x = ((first + i).template cast<double>() + Vector::Constant(0.5)) * h;
        Eigen::Vector3d point = Eigen::Vector3d::Zero();
        point.head<Dim>() = x;
        if (body.distance(point).distance < 0.0)
            particles.add(x, sampling.velocity, sampling.density * volume, volume, sampling.material);
    });
    return particles;
}

template <int Dim>
Particles<Dim> sample_ball(const Eigen::Matrix<double, Dim, 1>& center, double radius,
                           const LatticeSampling<Dim>& sampling)
{
    check_sampling(sampling, "ball");
    if (!center.allFinite() || !(std::isfinite(radius) && radius > 0.0))
        throw InputError("ball: the center must be finite and the radius a positive number");
    const double h = sampling.dx / sampling.per_cell;
    // lattice points center + k h, |k_a| ≤ m: an odd count centred on the center
    const double m = std::floor(radius / h);
    const auto n = lattice_counts<Dim>(Eigen::Matrix<double, Dim, 1>::Constant((2.0 * m + 1.0) * h), h, "ball");
    const double volume = std::pow(h, Dim);
    Particles<Dim> particles;
    for_each_lattice_point<Dim>(n, [&](const Eigen::Matrix<long long, Dim, 1>& i) {
        const Eigen::Matrix<double, Dim, 1> offset =
            (i.template cast<double>() - Eigen::Matrix<double, Dim, 1>::Constant(m)) * h;
        if (offset.norm() < radius)
            particles.add(center + offset, sampling.velocity, sampling.density * volume, volume, sampling.material);
    });
    return particles;  // never empty: the center is a lattice point
}

template <int Dim>
Particles<Dim> sample_mesh_elements(const Mesh& mesh, double density)
{
    const ElementKind kind = Dim == 3 ? ElementKind::tetrahedron : ElementKind::triangle_2d;
    if (mesh.kind != kind)
        throw InputError("mesh elements become particles for " + to_string(kind) + " meshes only, not " +
                         to_string(mesh.kind));
    if (mesh.num_elements() == 0)
        throw InputError("the mesh has no elements to make particles of");
    if (!(std::isfinite(density) && density > 0.0))
        throw InputError("mesh particles: density must be a positive number");
    Particles<Dim> particles;
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const double volume = element_measure(mesh, e);
        if (!(volume > 0.0))
            throw InputError("mesh element " + std::to_string(e) + " has non-positive volume " + std::to_string(volume));
        Eigen::Matrix<double, Dim, 1> centroid = Eigen::Matrix<double, Dim, 1>::Zero();
        for (int k = 0; k < mesh.elements.rows(); ++k)
            centroid += mesh.nodes.col(mesh.elements(k, e)).template head<Dim>();
        centroid /= static_cast<double>(mesh.elements.rows());
        particles.add(centroid, Eigen::Matrix<double, Dim, 1>::Zero(), density * volume, volume,
                      mesh.element_groups.empty() ? 0 : mesh.element_groups[static_cast<std::size_t>(e)]);
        if (mesh.element_fibers.cols() == mesh.num_elements())
            particles.point.back().fiber = mesh.element_fibers.col(e).template head<Dim>();
    }
    return particles;
}

template Particles<2> sample_box<2>(const Eigen::Vector2d&, const Eigen::Vector2d&, const LatticeSampling<2>&);
template Particles<3> sample_box<3>(const Eigen::Vector3d&, const Eigen::Vector3d&, const LatticeSampling<3>&);
template Particles<2> sample_inside<2>(const CollisionBody&, const Eigen::Vector2d&, const Eigen::Vector2d&,
                                      const LatticeSampling<2>&);
template Particles<3> sample_inside<3>(const CollisionBody&, const Eigen::Vector3d&, const Eigen::Vector3d&,
                                      const LatticeSampling<3>&);
template Particles<2> sample_ball<2>(const Eigen::Vector2d&, double, const LatticeSampling<2>&);
template Particles<3> sample_ball<3>(const Eigen::Vector3d&, double, const LatticeSampling<3>&);
template Particles<2> sample_mesh_elements<2>(const Mesh&, double);
template Particles<3> sample_mesh_elements<3>(const Mesh&, double);

} // namespace sinew
