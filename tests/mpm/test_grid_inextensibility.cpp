// AnisoMPM's fibre inextensibility on the grid (seed 004 §4, Alg. 11;
// issue 34): the cells' basis, the rows B and what they must and must not
// constrain, the seed's Schur-CG projection against a dense KKT solve, the
// rows as constraints of the implicit NLP (derivatives, every strategy
// against kkt-newton, relaxed-kkt and penalty as 1/κ), and the drift of
// |F a₀|² − 1 with and without its corrections.
#include "energies/deformation_regimes.hpp"

#include "sinew/energies/models/model_catalog.hpp"
#include "sinew/mpm/explicit_step.hpp"
#include "sinew/mpm/grid_velocity_map.hpp"
#include "sinew/mpm/grid_velocity_nlp.hpp"
#include "sinew/mpm/implicit_step.hpp"
#include "sinew/mpm/inextensibility/cell_basis.hpp"
#include "sinew/mpm/inextensibility/fiber_drift.hpp"
#include "sinew/mpm/inextensibility/inextensibility_rows.hpp"
#include "sinew/mpm/inextensibility/schur_projection.hpp"
#include "sinew/mpm/particle_sampling.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/runs/jacobi_cg.hpp"
#include "sinew/solvers/solver.hpp"

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace sinew;
using namespace sinew::test;

namespace {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;

template <int Dim>
std::unique_ptr<ConstitutiveModel<Dim, Dim>> neo_hookean(double mu, double lambda)
{
    return make_model<Dim, Dim>("stable-neo-hookean", ParameterValues{{"mu", mu}, {"lambda", lambda}});
}

InextensibilitySettings all_inextensible()
{
    InextensibilitySettings settings;
    settings.inextensible = {1};
    return settings;
}

/// A block [0.3, 0.5]^Dim sampled at dx = 0.05, two particles a cell edge,
/// each with a random unit fibre, F drawn for `regime` and a random velocity.
template <int Dim>
Particles<Dim> random_fibrous_block(Regime regime, std::mt19937& rng)
{
    LatticeSampling<Dim> sampling;
    sampling.dx = 0.05;
    Particles<Dim> particles = sample_box<Dim>(Vec<Dim>::Constant(0.3), Vec<Dim>::Constant(0.5), sampling);
    std::normal_distribution<double> normal;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        particles.F[i] = random_deformation<Dim, Dim>(regime, rng);
        for (int a = 0; a < Dim; ++a) {
            particles.v[i][a] = 0.3 * normal(rng);
            particles.point[i].fiber[a] = normal(rng);
        }
        particles.point[i].fiber.normalize();
    }
    return particles;
}

/// The grid of the particles' P2G, with gravity, and the map of the implicit predictor.
template <int Dim>
struct GridStep {
    MpmStepSettings<Dim> settings;
    SparseGrid<Dim> grid{0.05};
    ParticleBuckets<Dim> layout;
    std::unique_ptr<GridVelocityMap<Dim>> map;

    GridStep(const Particles<Dim>& particles, const std::optional<GridWalls<Dim>>& walls)
    {
        settings.time_step = 0.01;
        settings.gravity[Dim - 1] = -9.81;
        settings.walls = walls;
        layout = particles_to_grid(particles, settings.transfer, grid);
        map = std::make_unique<GridVelocityMap<Dim>>(particles, grid, settings,
                                                     GridVelocityMap<Dim>::Predictor::momentum_and_gravity);
    }
};

/// y with v_i = field(x_i) at every free node (held nodes keep their frames' v_b).
template <int Dim, typename Field>
Eigen::VectorXd unknowns_of(const GridVelocityMap<Dim>& map, double dx, const Field& field)
{
    Eigen::VectorXd y(map.variables());
    for (int k = 0; k < map.nodes(); ++k) {
        const auto& frame = map.frame(k);
        if (frame.basis.cols() > 0)
            y.segment(map.first_variable(k), frame.basis.cols()) =
                frame.basis.transpose() * (field(Vec<Dim>(map.index(k).template cast<double>() * dx)) - frame.offset);
    }
    return y;
}

/// The dense KKT solution of min ½ (y − y*)ᵀ M (y − y*) s.t. B y = rhs
/// (least squares on a singular system: rows may depend on each other).
Eigen::VectorXd dense_projection(const LinearVelocityRows& rows, const Eigen::VectorXd& masses, const Eigen::VectorXd& target)
{
    const Eigen::Index n = masses.size(), m = rows.rows();
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + m, n + m);
    K.topLeftCorner(n, n) = masses.asDiagonal();
    K.bottomLeftCorner(m, n) = Eigen::MatrixXd(rows.B);
    K.topRightCorner(n, m) = Eigen::MatrixXd(rows.B).transpose();
    Eigen::VectorXd b(n + m);
    b << masses.cwiseProduct(target), rows.rhs;
    return K.completeOrthogonalDecomposition().solve(b).head(n);
}

/// A rope of soft, inextensible particles (fibres along it) hanging from
/// sticky walls at its top, a heavier ball of another material at its foot.
struct HangingRope {
    Particles<2> particles;
    std::unique_ptr<ConstitutiveModel<2, 2>> rope_model = neo_hookean<2>(200.0, 400.0);
    std::unique_ptr<ConstitutiveModel<2, 2>> ball_model = neo_hookean<2>(1e4, 2e4);
    std::vector<const ConstitutiveModel<2, 2>*> models{rope_model.get(), ball_model.get()};
    MpmStepSettings<2> settings;
    InextensibilitySettings inextensibility;

    explicit HangingRope(double dx)
    {
        LatticeSampling<2> rope;
        rope.dx = dx;
        rope.density = 100.0;
        particles = sample_box<2>(Eigen::Vector2d(0.48, 0.5), Eigen::Vector2d(0.52, 0.97), rope);
        for (auto& point : particles.point)
            point.fiber = Eigen::Vector2d::UnitY();
        LatticeSampling<2> ball = rope;
        ball.density = 500.0;
        ball.material = 1;
        const Particles<2> weight = sample_ball<2>(Eigen::Vector2d(0.5, 0.44), 0.06, ball);
        for (int p = 0; p < weight.size(); ++p)
            particles.add(weight.x[static_cast<std::size_t>(p)], weight.v[static_cast<std::size_t>(p)],
                          weight.mass[static_cast<std::size_t>(p)], weight.volume[static_cast<std::size_t>(p)], 1);
        settings.gravity = Eigen::Vector2d(0.0, -9.81);
        GridWalls<2> walls = GridWalls<2>::box(Eigen::Vector2d::Zero(), Eigen::Vector2d::Ones(), GridCondition::sticky);
        walls.thickness = 4.0;
        settings.walls = walls;
        inextensibility.inextensible = {1, 0};
    }

    /// The lowest rope particle's height.
    double rope_foot() const
    {
        double lowest = 1.0;
        for (int p = 0; p < particles.size(); ++p)
            if (particles.material[static_cast<std::size_t>(p)] == 0)
                lowest = std::min(lowest, particles.x[static_cast<std::size_t>(p)].y());
        return lowest;
    }
};

GridVelocitySolve solve_with(const std::string& solver, std::map<std::string, std::string> backend = {})
{
    return [solver, backend](Nlp& nlp, Eigen::VectorXd& v) {
        SolverOptions options;
        options.tolerance = 1e-12;
        options.kkt_tolerance = 1e-10;
        options.backend = backend;
        const Result result = solve(nlp, solver, options);
        v = result.x;
        return result.status == Status::converged;
    };
}

} // namespace

TEST_CASE("grid inextensibility: the cell basis is a partition of unity that reproduces linear fields")
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uniform(-2.0, 2.0);
    const double dx = 0.07;
    for (int trial = 0; trial < 50; ++trial) {
        Eigen::Vector3d x(uniform(rng), uniform(rng), uniform(rng));
        double total = 0.0;
        Eigen::Vector3d reproduced = Eigen::Vector3d::Zero();
        cell_stencil<3>(x, dx).for_each([&](const Eigen::Vector3i& cell, double gamma) {
            CHECK(gamma >= 0.0);
            total += gamma;
            reproduced += gamma * (cell.cast<double>() + Eigen::Vector3d::Constant(0.5)) * dx;  // Σ Γ_c x_c
        });
        CHECK(std::abs(total - 1.0) < 1e-14);
        CHECK((reproduced - x).norm() < 1e-14);
    }
}

TEMPLATE_TEST_CASE_SIG("grid inextensibility: rigid motions satisfy the rows and stretch along the fibres does not", "",
                       ((int Dim), Dim), 2, 3)
{
    std::mt19937 rng(5 + Dim);
    for (const Regime regime : {Regime::near_identity, Regime::large_stretch, Regime::compression, Regime::rotated}) {
        CAPTURE(regime_name(regime));
        const Particles<Dim> particles = random_fibrous_block<Dim>(regime, rng);
        const GridStep<Dim> step(particles, std::nullopt);
        const LinearVelocityRows rows = inextensibility_rows(particles, *step.map, 0.05, all_inextensible());
        REQUIRE(rows.rows() > 0);
        CHECK(rows.rhs.cwiseAbs().maxCoeff() == 0.0);  // no walls: no offsets
        // v = b + W x, W skew: aᵀ ∇v a = aᵀ W a = 0 for every fibre (MLS reproduces affine fields).
        const Vec<Dim> b = Vec<Dim>::Random();
        Eigen::Matrix<double, Dim, Dim> W = Eigen::Matrix<double, Dim, Dim>::Random();
        W = (W - W.transpose()).eval();
        const Eigen::VectorXd rigid = unknowns_of<Dim>(*step.map, 0.05, [&](const Vec<Dim>& x) { return Vec<Dim>(b + W * x); });
        CHECK(rows.violation(rigid) < 1e-11 * rigid.cwiseAbs().maxCoeff());
        // v = G x: each row is the cell's mean of aᵀ G a = (F a₀)ᵀ G (F a₀), the fibres' strain rate.
        const Eigen::Matrix<double, Dim, Dim> G = Eigen::Matrix<double, Dim, Dim>::Random();
        const Eigen::VectorXd affine = unknowns_of<Dim>(*step.map, 0.05, [&](const Vec<Dim>& x) { return Vec<Dim>(G * x); });
        const Eigen::VectorXd rates = rows.B * affine;
        double smallest = rates.cwiseAbs().maxCoeff(), largest = 0.0;
        for (int p = 0; p < particles.size(); ++p) {
            const Vec<Dim> a = particles.F[static_cast<std::size_t>(p)] * particles.point[static_cast<std::size_t>(p)].fiber;
            smallest = std::min(smallest, a.dot(G * a));
            largest = std::max(largest, a.dot(G * a));
        }
        // Each row is a weighted mean of the particles' rates: within their range, and not all zero.
        CHECK(rates.minCoeff() >= smallest - 1e-10);
        CHECK(rates.maxCoeff() <= largest + 1e-10);
        CHECK(rates.cwiseAbs().maxCoeff() > 1e-3);
    }
}

TEST_CASE("grid inextensibility: fibres along x feel a stretch along x exactly, and a stretch along y not at all")
{
    LatticeSampling<2> sampling;
    sampling.dx = 0.05;
    const Particles<2> particles = sample_box<2>(Eigen::Vector2d(0.3, 0.3), Eigen::Vector2d(0.6, 0.5), sampling);
    const GridStep<2> step(particles, std::nullopt);
    const LinearVelocityRows rows = inextensibility_rows(particles, *step.map, 0.05, all_inextensible());
    const double epsilon = 0.7;
    const Eigen::VectorXd along = unknowns_of<2>(*step.map, 0.05, [&](const Eigen::Vector2d& x) {
        return Eigen::Vector2d(epsilon * x.x(), 0.0);
    });
    const Eigen::VectorXd across = unknowns_of<2>(*step.map, 0.05, [&](const Eigen::Vector2d& x) {
        return Eigen::Vector2d(0.0, epsilon * x.y());
    });
    CHECK((rows.B * along - Eigen::VectorXd::Constant(rows.rows(), epsilon)).cwiseAbs().maxCoeff() < 1e-12);
    CHECK((rows.B * across).cwiseAbs().maxCoeff() < 1e-12);
}

TEMPLATE_TEST_CASE_SIG("grid inextensibility: the Schur-CG projection satisfies the rows and is the KKT solution", "",
                       ((int Dim), Dim), 2, 3)
{
    std::mt19937 rng(11 + Dim);
    GridWalls<Dim> walls = GridWalls<Dim>::box(Vec<Dim>::Constant(0.33), Vec<Dim>::Constant(0.9), GridCondition::sticky);
    walls.condition[0][0] = GridCondition::slip;
    walls.thickness = 1.0;
    for (const bool with_walls : {false, true}) {
        CAPTURE(with_walls);
        const Particles<Dim> particles = random_fibrous_block<Dim>(Regime::moderate, rng);
        const GridStep<Dim> step(particles, with_walls ? std::optional<GridWalls<Dim>>(walls) : std::nullopt);
        const LinearVelocityRows rows = inextensibility_rows(particles, *step.map, 0.05, all_inextensible());
        const Eigen::VectorXd target = step.map->predictor();
        const Eigen::VectorXd masses = step.map->variable_masses();
        Eigen::VectorXd y = target;
        const SchurProjectionReport report = project_onto_rows(rows, masses, y, jacobi_cg(1e-12, 10000));
        CHECK(report.solve.converged);
        CHECK(report.violation_before > 1e-2);
        CHECK(report.violation_after < 1e-9 * report.violation_before);
        const Eigen::VectorXd reference = dense_projection(rows, masses, target);
        CHECK((y - reference).cwiseAbs().maxCoeff() < 1e-8 * target.cwiseAbs().maxCoeff());
    }
}

TEST_CASE("grid inextensibility: independent_rows drops the rows that depend on others and keeps the solutions")
{
    std::mt19937 rng(19);
    const Particles<2> particles = random_fibrous_block<2>(Regime::moderate, rng);
    const GridStep<2> step(particles, std::nullopt);
    const LinearVelocityRows rows = inextensibility_rows(particles, *step.map, 0.05, all_inextensible());
    // Append combinations of the rows: 2 r₀ − r₃, and r₁ + r₂ + r₅ with its right-hand side.
    LinearVelocityRows redundant;
    const int m = rows.rows();
    redundant.B.resize(m + 2, rows.B.cols());
    Eigen::SparseMatrix<double, Eigen::RowMajor> combine(m + 2, m);
    std::vector<Eigen::Triplet<double>> weights;
    for (int r = 0; r < m; ++r)
        weights.emplace_back(r, r, 1.0);
    weights.insert(weights.end(), {{m, 0, 2.0}, {m, 3, -1.0}, {m + 1, 1, 1.0}, {m + 1, 2, 1.0}, {m + 1, 5, 1.0}});
    combine.setFromTriplets(weights.begin(), weights.end());
    redundant.B = combine * rows.B;
    redundant.rhs = combine * Eigen::VectorXd::Random(m);
    const LinearVelocityRows kept = independent_rows(redundant);
    const Eigen::MatrixXd dense = Eigen::MatrixXd(rows.B);
    const auto rank = Eigen::ColPivHouseholderQR<Eigen::MatrixXd>(dense.transpose()).rank();
    CHECK(kept.rows() == rank);
    CHECK(kept.rows() < redundant.rows());
    // The same solutions: the least-norm solution of the kept rows meets all of them.
    const Eigen::VectorXd y = Eigen::MatrixXd(kept.B).completeOrthogonalDecomposition().solve(kept.rhs);
    CHECK(redundant.violation(y) < 1e-10 * redundant.rhs.cwiseAbs().maxCoeff());
}

TEST_CASE("grid inextensibility: the constrained implicit NLP's Jacobian is the rows, by central differences")
{
    std::mt19937 rng(17);
    const auto model = neo_hookean<2>(1e3, 2e3);
    const std::vector<const ConstitutiveModel<2, 2>*> models{model.get()};
    for (const Regime regime : {Regime::near_identity, Regime::large_stretch, Regime::compression, Regime::near_inversion}) {
        CAPTURE(regime_name(regime));
        const Particles<2> particles = random_fibrous_block<2>(regime, rng);
        GridStep<2> step(particles, std::nullopt);
        LinearVelocityRows rows = inextensibility_rows(particles, *step.map, 0.05, all_inextensible());
        GridVelocityNlp<2> nlp(particles, models, std::move(*step.map), step.layout, 0.01, rows);
        const Eigen::VectorXd y = nlp.starting_point() + 0.01 * Eigen::VectorXd::Random(nlp.num_variables());
        const DerivativeCheckReport report = check_derivatives(nlp, y);
        INFO(report.to_text());
        CHECK(report.passed(1e-5));
        Eigen::VectorXd c(nlp.num_constraints());
        nlp.constraints(y, c);
        CHECK((c - rows.B * y).norm() == 0.0);
    }
}

TEST_CASE("grid inextensibility: every strategy that converges on the constrained step finds kkt-newton's velocities")
{
    HangingRope rope(0.05);
    SparseGrid<2> grid(0.05);
    const ParticleBuckets<2> layout = particles_to_grid(rope.particles, rope.settings.transfer, grid);
    rope.settings.time_step = 0.01;
    auto constrained = [&] {
        GridVelocityMap<2> map(rope.particles, grid, rope.settings, GridVelocityMap<2>::Predictor::momentum_and_gravity);
        LinearVelocityRows rows = inextensibility_rows(rope.particles, map, 0.05, rope.inextensibility);
        return std::make_unique<GridVelocityNlp<2>>(rope.particles, rope.models, std::move(map), layout, 0.01, rows);
    };
    // The distance in the kinetic metric M (relative): a fringe node of tiny
    // mass moves its velocity at almost no cost, so the plain ∞-norm would
    // compare what the step leaves undetermined.
    const Eigen::VectorXd masses = constrained()->map().variable_masses();
    auto distance = [&](const Eigen::VectorXd& y, const Eigen::VectorXd& reference) {
        return std::sqrt((masses.array() * (y - reference).array().square()).sum() /
                         (masses.array() * reference.array().square()).sum());
    };
    auto solved = [&](const std::string& solver, std::map<std::string, std::string> backend, bool must_converge) {
        const auto nlp = constrained();
        Eigen::VectorXd y = nlp->starting_point();
        CAPTURE(solver);
        const bool converged = solve_with(solver, backend)(*nlp, y);
        if (must_converge)
            CHECK(converged);
        return y;
    };
    const auto nlp = constrained();
    REQUIRE(nlp->num_constraints() > 0);
    const Eigen::VectorXd reference = solved("kkt-newton", {}, true);
    CHECK(nlp->rows().violation(reference) < 1e-9);
    for (const std::string solver : {"augmented-lagrangian", "ipopt"}) {
        CAPTURE(solver);
        CHECK(distance(solved(solver, {}, true), reference) < 1e-8);
    }
    // relaxed-kkt and penalty miss the constraint by O(1/κ) (seed 004 §4.3):
    // κ times their distance and κ times their violation stay put.
    for (const auto& solver : all_solvers()) {
        if (!takes_kappa(*solver))
            continue;
        CAPTURE(solver->name());
        std::vector<double> scaled_distances, scaled_violations;
        for (const double kappa : {1e3, 1e4, 1e5}) {
            const Eigen::VectorXd y = solved(solver->name(), solver->fixed_kappa_options(kappa), false);
            scaled_distances.push_back(kappa * distance(y, reference));
            scaled_violations.push_back(kappa * nlp->rows().violation(y));
        }
        CAPTURE(scaled_distances, scaled_violations);
        CHECK(scaled_distances[0] > 0.0);
        for (const auto* scaled : {&scaled_distances, &scaled_violations}) {
            CHECK(std::abs((*scaled)[1] / (*scaled)[0] - 1.0) < 0.2);
            CHECK(std::abs((*scaled)[2] / (*scaled)[1] - 1.0) < 0.2);
        }
    }
}
