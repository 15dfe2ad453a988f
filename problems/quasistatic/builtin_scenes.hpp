#pragma once
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"

#include <memory>
#include <vector>

namespace sinew {

/// The cantilever of issue 4: beam [0, 1] × [0, 0.2] × [0, 0.2] m of
/// `cells_across` × `cells_across` × 5·`cells_across` cubes, 6 tets each
/// (6·5·n³ tets); the Mooney-Rivlin part of the muscle model (A = 1e4,
/// B = 1e3, K = 1e5 Pa, sigma_max = 0: no fiber term), 1000 kg/m³ under
/// gravity 9.81 m/s² along −z, the nodes at x = 0 clamped. Twisted: the nodes
/// at x = 1 also turned 45° about the beam's axis (y = z = 0.1) and moved
/// +0.1 m along x.
std::unique_ptr<QuasistaticProblem> make_cantilever(int cells_across, bool twisted,
                                                    DirichletStrategy dirichlet = DirichletStrategy::eliminate);

/// The cantilever scenes, straight and twisted: about 6k tets in suite
/// `quasistatic`, about 52k and 206k in `quasistatic-large`.
/// No published optimum: a run counts when it converges.
std::vector<BuiltinProblem> quasistatic_scenes();

} // namespace sinew
