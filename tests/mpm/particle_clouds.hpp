#pragma once
// Particle sets for the MPM tests: random positions in a box, several per
// cell, with random masses, velocities and affine matrices.
#include "sinew/mpm/particles.hpp"

#include <random>

namespace sinew::test {

/// `count` particles uniformly in [lower, upper]^Dim with masses in [0.5, 1.5],
/// velocities and C entries normal with the given scales.
template <int Dim>
Particles<Dim> random_particles(int count, double lower, double upper, double velocity_scale, double affine_scale,
                                unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> position(lower, upper), mass(0.5, 1.5);
    std::normal_distribution<double> normal;
    Particles<Dim> particles;
    for (int p = 0; p < count; ++p) {
        Eigen::Matrix<double, Dim, 1> x, v;
        for (int a = 0; a < Dim; ++a) {
            x[a] = position(rng);
            v[a] = velocity_scale * normal(rng);
        }
        particles.add(x, v, mass(rng), 1e-3);
        for (int a = 0; a < Dim; ++a)
            for (int b = 0; b < Dim; ++b)
                particles.C.back()(a, b) = affine_scale * normal(rng);
    }
    return particles;
}

} // namespace sinew::test
