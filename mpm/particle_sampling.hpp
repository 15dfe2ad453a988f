#pragma once
#include "sinew/bodies/collision_body.hpp"
#include "sinew/mesh/mesh.hpp"
#include "sinew/mpm/particles.hpp"

namespace sinew {

/// How a shape is filled with particles: a regular lattice of
/// `per_cell` particles along each cell edge of dx (per_cell^Dim a cell),
/// each of mass density · its volume, all with `velocity` and `material`.
template <int Dim>
struct LatticeSampling {
    double dx = 0.1;
    int per_cell = 2;
    double density = 1000.0;
    Eigen::Matrix<double, Dim, 1> velocity = Eigen::Matrix<double, Dim, 1>::Zero();
    int material = 0;
};

/// The most particles one sampling makes (10⁸, about 25 GB of particles):
/// a request beyond is an input error, not an allocation failure.
inline constexpr double kMaxSampledParticles = 1e8;

/// The box [lower, upper] filled exactly: along each axis n = round(extent /
/// (dx/per_cell)) particles (at least 1) at the centres of n equal
/// intervals, so that their volumes sum to the box's. InputError for
/// dx ≤ 0, per_cell < 1, density ≤ 0, a box that is empty or inverted, any
/// value not finite, or more than kMaxSampledParticles particles.
template <int Dim>
Particles<Dim> sample_box(const Eigen::Matrix<double, Dim, 1>& lower, const Eigen::Matrix<double, Dim, 1>& upper,
                          const LatticeSampling<Dim>& sampling);

/// The lattice points of spacing dx/per_cell (centred on `center`) inside
/// the ball |x − center| < radius, each of volume (dx/per_cell)^Dim: their
/// volumes approach the ball's as the spacing shrinks. A disk in 2D.
/// InputError as sample_box, and for a radius ≤ 0.
template <int Dim>
Particles<Dim> sample_ball(const Eigen::Matrix<double, Dim, 1>& center, double radius,
                           const LatticeSampling<Dim>& sampling);

/// The lattice points (k + ½)·dx/per_cell (aligned with the grid) in the box
/// [lower, upper] that lie inside `body` (φ < 0; a closed surface, a level
/// set, an analytic body), each of volume (dx/per_cell)^Dim: their volumes
/// approach the body's as the spacing shrinks. InputError as sample_box, and
/// for a body of another dimension; an empty result when no lattice point
/// lies inside (the caller says what that means).
template <int Dim>
Particles<Dim> sample_inside(const CollisionBody& body, const Eigen::Matrix<double, Dim, 1>& lower,
                             const Eigen::Matrix<double, Dim, 1>& upper, const LatticeSampling<Dim>& sampling);

/// One particle per element of a tetrahedral (3D) or planar triangle (2D)
/// mesh, at its centroid, with the element's rest volume, its fiber when the
/// mesh has them and its group as the material index; mass density · volume.
/// InputError for another element kind, a mesh without elements, an
/// element of non-positive volume, or density ≤ 0.
template <int Dim>
Particles<Dim> sample_mesh_elements(const Mesh& mesh, double density);

} // namespace sinew
