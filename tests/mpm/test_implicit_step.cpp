// The implicit MLS-MPM step (issue 33): the grid-velocity NLP's gradient and
// Hessian against the Taylor test and central differences in every regime of
// F, 2D and 3D; its F_p(v) is the F the transfers then give; every strategy
// that accepts it finds the same step; implicit and explicit steps agree as
// Δt → 0; the implicit step stays stable at 10× the explicit CFL bound, where
// the explicit step blows up.
#include "energies/deformation_regimes.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/core/threads.hpp"
#include "sinew/energies/models/model_catalog.hpp"
#include "sinew/energies/models/qr_anisotropic.hpp"
#include "sinew/mpm/cfl.hpp"
#include "sinew/mpm/explicit_step.hpp"
#include "sinew/mpm/grid_velocity_nlp.hpp"
#include "sinew/mpm/implicit_step.hpp"
#include "sinew/mpm/particle_measures.hpp"
#include "sinew/mpm/particle_sampling.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/taylor_test.hpp"
#include "sinew/solvers/solver.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>

#include <cmath>
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
std::unique_ptr<ConstitutiveModel<Dim, Dim>> lame_model(const std::string& name, double mu, double lambda)
{
    return make_model<Dim, Dim>(name, ParameterValues{{"mu", mu}, {"lambda", lambda}});
}

/// A block of 2 × … cells of dx = 0.1 at 0.3…0.5, two particles a cell
/// edge, each with F drawn for `regime` and a random velocity.
template <int Dim>
Particles<Dim> deformed_block(Regime regime, std::mt19937& rng)
{
    LatticeSampling<Dim> sampling;
    sampling.dx = 0.1;
    Particles<Dim> particles = sample_box<Dim>(Vec<Dim>::Constant(0.3), Vec<Dim>::Constant(0.5), sampling);
    std::normal_distribution<double> normal;
    for (int p = 0; p < particles.size(); ++p) {
        const auto i = static_cast<std::size_t>(p);
        particles.F[i] = random_deformation<Dim, Dim>(regime, rng);
        for (int a = 0; a < Dim; ++a)
            particles.v[i][a] = 0.1 * normal(rng);
    }
    return particles;
}

/// A solve by the named strategy to a relative gradient of 1e-10.
GridVelocitySolve solve_with(const std::string& solver)
{
    return [solver](Nlp& nlp, Eigen::VectorXd& v) {
        SolverOptions options;
        options.tolerance = 1e-10;
        options.kkt_tolerance = 1e-9;
        const Result result = solve(nlp, solver, options);
        v = result.x;
        return result.status == Status::converged;
    };
}

/// Kinetic, elastic and gravitational energy (height above y = 0 or z = 0).
template <int Dim>
double total_energy(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                    double g)
{
    double potential = 0.0;
    for (int p = 0; p < particles.size(); ++p)
        potential += particles.mass[static_cast<std::size_t>(p)] * g * particles.x[static_cast<std::size_t>(p)][Dim - 1];
    return kinetic_energy(particles) + elastic_energy(particles, models) + potential;
}

/// The NLP of one step of a deformed block, F of every particle drawn for
/// `regime`: Taylor test, central differences, and a PSD projected Hessian.
template <int Dim>
void check_grid_velocity_nlp(const std::vector<const ConstitutiveModel<Dim, Dim>*>& models, Regime regime,
                             const std::optional<GridWalls<Dim>>& walls, std::mt19937& rng, bool damaged = false)
{
    CAPTURE(models[0]->name(), Dim, regime_name(regime), walls.has_value(), damaged);
    Particles<Dim> particles = deformed_block<Dim>(regime, rng);
    if (damaged) {  // d and the fibre random per particle (seed 004 §3.6: the degraded momentum)
        std::uniform_real_distribution<double> u01(0.0, 1.0);
        for (auto& point : particles.point) {
            point.damage = u01(rng);
            point.fiber = random_unit_vector<Dim>(rng);
        }
    }
    SparseGrid<Dim> grid(0.1);
    const ParticleBuckets<Dim> layout = particles_to_grid(particles, TransferSettings{}, grid);
    // Δt² μ /(ρ dx²) = 25: the elastic term outweighs inertia in the Hessian.
    MpmStepSettings<Dim> settings;
    settings.time_step = 0.05;
    settings.gravity = Vec<Dim>::Constant(-9.81);
    settings.walls = walls;
    GridVelocityNlp<Dim> nlp(particles, models, grid, layout, settings);
    if (walls)
        CHECK((nlp.num_variables() > 0 && nlp.num_variables() < Dim * nlp.nodes()));
    else
        CHECK(nlp.num_variables() == Dim * nlp.nodes());
    Eigen::VectorXd v = nlp.starting_point();
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    for (int k = 0; k < v.size(); ++k)
        v[k] += 0.02 * u11(rng);
    REQUIRE(std::isfinite(nlp.objective(v)));
    const TaylorReport taylor = taylor_test(nlp, v);
    CAPTURE(taylor.to_text());
    CHECK(taylor.passed());
    CHECK(taylor.hessian.worst.verdict != TaylorVerdict::exact);
    const DerivativeCheckReport entrywise = check_derivatives(nlp, v);
    CAPTURE(entrywise.to_text());
    CHECK(entrywise.passed(1e-5));
    // The projected Hessian is PSD (each particle's term is).
    const int n = nlp.num_variables();
    Eigen::VectorXd values(nlp.hessian_pattern().nonzeros());
    nlp.hessian(v, 1.0, Eigen::VectorXd(), Projection::clamp, values);
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
    for (int k = 0; k < values.size(); ++k) {
        H(nlp.hessian_pattern().rows[k], nlp.hessian_pattern().cols[k]) += values[k];
        if (nlp.hessian_pattern().rows[k] != nlp.hessian_pattern().cols[k])
            H(nlp.hessian_pattern().cols[k], nlp.hessian_pattern().rows[k]) += values[k];
    }
    CHECK(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H).eigenvalues().minCoeff() >= -1e-10 * H.norm());
}

template <int Dim>
void check_grid_velocity_derivatives(const std::string& model_name, unsigned seed)
{
    std::mt19937 rng(seed);
    const auto model = lame_model<Dim>(model_name, 1e5, 2e5);
    const std::vector<const ConstitutiveModel<Dim, Dim>*> models{model.get()};
    // Without walls, and with walls one cell deep around the block: slip on
    // the lower faces, sticky on the upper, so that held nodes move in their frames.
    GridWalls<Dim> walls = GridWalls<Dim>::box(Vec<Dim>::Constant(0.2), Vec<Dim>::Constant(0.65), GridCondition::slip);
    walls.thickness = 1.0;
    for (auto& faces : walls.condition)
        faces[1] = GridCondition::sticky;
    for (const bool walled : {false, true}) {
        for (const Regime regime : all_regimes())
            check_grid_velocity_nlp<Dim>(models, regime, walled ? std::optional<GridWalls<Dim>>(walls) : std::nullopt, rng);
    }
}

} // namespace

TEST_CASE("implicit MPM: the grid-velocity NLP passes the Taylor test and central differences in every regime, 2D")
{
    check_grid_velocity_derivatives<2>("fixed-corotated", 11);
    check_grid_velocity_derivatives<2>("stable-neo-hookean", 12);
}

TEST_CASE("implicit MPM: the grid-velocity NLP passes the Taylor test and central differences in every regime, 3D")
{
    check_grid_velocity_derivatives<3>("fixed-corotated", 13);
    check_grid_velocity_derivatives<3>("stable-neo-hookean", 14);
}

TEST_CASE("implicit MPM: the grid-velocity NLP of damaged qr-anisotropic particles passes the derivative checks")
{
    // The degraded model's ∂P/∂F jumps at J = 1 where d > 0 (g on the volume
    // term for J ≥ 1 only), so the regimes here keep every J away from 1:
    // stretched and compressed blocks; residual r = 0 and 0.1.
    for (const double residual : {0.0, 0.1}) {
        CAPTURE(residual);
        const QrAnisotropic<2> plane(ParameterValues{{"mu", 1e5}, {"lambda", 2e5}, {"kx", 3e5}, {"residual", residual}});
        const QrAnisotropic<3> volume(ParameterValues{{"mu", 1e5}, {"lambda", 2e5}, {"kx", 3e5}, {"residual", residual}});
        std::mt19937 rng(31);
        for (const Regime regime : {Regime::large_stretch, Regime::compression}) {
            check_grid_velocity_nlp<2>({&plane}, regime, std::nullopt, rng, true);
            check_grid_velocity_nlp<3>({&volume}, regime, std::nullopt, rng, true);
        }
    }
}

TEST_CASE("implicit MPM: F_p(v) of the NLP is the F the transfers and the advection give the particle")
{
    std::mt19937 rng(21);
    const auto model = lame_model<3>("fixed-corotated", 1e5, 2e5);
    const std::vector<const Model3d*> models{model.get()};
    Particles<3> particles = deformed_block<3>(Regime::moderate, rng);
    MpmStepSettings<3> settings;
    settings.time_step = 0.01;
    SparseGrid<3> grid(0.1);
    const ParticleBuckets<3> layout = particles_to_grid(particles, settings.transfer, grid);
    GridVelocityNlp<3> nlp(particles, models, grid, layout, settings);
    Eigen::VectorXd v = nlp.starting_point() + Eigen::VectorXd::Random(nlp.num_variables());
    std::vector<Eigen::Matrix3d> expected;
    for (int p = 0; p < particles.size(); ++p)
        expected.push_back(nlp.deformation(p, v));
    for (int k = 0; k < nlp.nodes(); ++k)
        grid.velocity[static_cast<std::size_t>(nlp.slot(k))] = nlp.velocity(k, v);
    finish_step(settings, grid, layout, particles);
    for (int p = 0; p < particles.size(); ++p)
        CHECK((particles.F[static_cast<std::size_t>(p)] - expected[static_cast<std::size_t>(p)]).norm() < 1e-13);
}

TEST_CASE("implicit MPM: the Hessian is the same bit for bit on one thread and on two")
{
    std::mt19937 rng(23);
    const auto model = lame_model<3>("stable-neo-hookean", 1e5, 2e5);
    const std::vector<const Model3d*> models{model.get()};
    const Particles<3> particles = deformed_block<3>(Regime::large_stretch, rng);
    MpmStepSettings<3> settings;
    settings.time_step = 0.01;
    SparseGrid<3> grid(0.1);
    const ParticleBuckets<3> layout = particles_to_grid(particles, settings.transfer, grid);
    GridVelocityNlp<3> nlp(particles, models, grid, layout, settings);
    const Eigen::VectorXd v = nlp.starting_point() + 0.1 * Eigen::VectorXd::Ones(nlp.num_variables());
    const Eigen::VectorXd none;
    std::vector<Eigen::VectorXd> values;
    for (const int count : {1, std::min(2, available_cores())}) {
        set_threads(count);
        for (const Projection projection : {Projection::none, Projection::clamp}) {
            values.emplace_back(nlp.hessian_pattern().nonzeros());
            nlp.hessian(v, 1.0, none, projection, values.back());
        }
    }
    set_threads(available_cores());
    if (available_cores() < 2)
        WARN("one core: both assemblies were on one thread");
    REQUIRE(values[0].size() > 0);
    CHECK(values[0].cwiseAbs().maxCoeff() > 0.0);
    CHECK((values[0].array() == values[2].array()).all());
    CHECK((values[1].array() == values[3].array()).all());
}

TEST_CASE("implicit MPM: every strategy that accepts the grid-velocity NLP finds the same step")
{
    std::mt19937 rng(31);
    const auto model = lame_model<2>("stable-neo-hookean", 1e5, 2e5);
    const std::vector<const Model2d*> models{model.get()};
    const Particles<2> start = deformed_block<2>(Regime::moderate, rng);
    MpmStepSettings<2> settings;
    settings.time_step = 0.02;
    settings.gravity = Eigen::Vector2d(0.0, -9.81);
    Particles<2> reference = start;
    SparseGrid<2> grid(0.1);
    REQUIRE(implicit_step(reference, models, settings, grid, solve_with("projected-newton")).converged);
    const double scale = std::sqrt(2.0 * kinetic_energy(reference) / total_mass(reference));
    REQUIRE(scale > 0.0);
    std::vector<std::string> compared;
    for (const auto& solver : all_solvers()) {
        if (solver->name() == "projected-newton")
            continue;
        SparseGrid<2> probe_grid(0.1);
        const ParticleBuckets<2> probe_layout = particles_to_grid(start, settings.transfer, probe_grid);
        GridVelocityNlp<2> probe(start, models, probe_grid, probe_layout, settings);
        if (solver->refusal(probe) || solver->name().rfind("nlopt", 0) == 0)
            continue;  // NLopt's tolerances are on steps, not on the gradient: not comparable at 1e-7
        CAPTURE(solver->name());
        Particles<2> particles = start;
        const ImplicitStepReport report = implicit_step(particles, models, settings, grid, solve_with(solver->name()));
        CHECK(report.converged);
        double worst = 0.0;
        for (int p = 0; p < particles.size(); ++p)
            worst = std::max(worst, (particles.v[static_cast<std::size_t>(p)] - reference.v[static_cast<std::size_t>(p)]).norm());
        CHECK(worst < 1e-7 * scale);
        compared.push_back(solver->name());
    }
    // Ipopt and interior-point take unconstrained problems; the constrained strategies refuse them.
    CHECK(compared == std::vector<std::string>{"ipopt", "interior-point"});
}

namespace {

/// A 2D block of 4 × 4 cells of dx = 0.1, two particles a cell edge, released
/// from a uniform stretch and shear (every particle's F), at rest.
Particles<2> stretched_block(double bottom)
{
    LatticeSampling<2> sampling;
    sampling.dx = 0.1;
    Particles<2> particles = sample_box<2>(Eigen::Vector2d(0.3, bottom), Eigen::Vector2d(0.7, bottom + 0.4), sampling);
    Eigen::Matrix2d F;
    F << 1.05, 0.03, 0.0, 0.97;
    for (auto& Fp : particles.F)
        Fp = F;
    return particles;
}

/// Positions after `steps` steps of Δt = duration/steps, explicit or implicit.
Particles<2> run_block(const std::vector<const Model2d*>& models, double duration, int steps, bool implicit)
{
    Particles<2> particles = stretched_block(0.3);
    MpmStepSettings<2> settings;
    settings.time_step = duration / steps;
    SparseGrid<2> grid(0.1);
    for (int n = 0; n < steps; ++n) {
        if (implicit)
            REQUIRE(implicit_step(particles, models, settings, grid, solve_with("projected-newton")).converged);
        else
            REQUIRE(explicit_step(particles, models, settings, grid).failure.empty());
    }
    return particles;
}

/// An explicit step: false when it fails or flings particles beyond the grid's domain.
bool explicit_step_stays_finite(Particles<2>& particles, const std::vector<const Model2d*>& models,
                                const MpmStepSettings<2>& settings, SparseGrid<2>& grid)
{
    try {
        return explicit_step(particles, models, settings, grid).failure.empty();
    } catch (const InputError&) {
        return false;
    }
}

} // namespace

TEST_CASE("implicit MPM: implicit and explicit steps agree as dt goes to 0, first order")
{
    const auto model = lame_model<2>("stable-neo-hookean", 1e4, 2e4);
    const std::vector<const Model2d*> models{model.get()};
    const double cfl = cfl_time_step(stretched_block(0.3), models, 0.1, 1.0);
    const double duration = 2.0 * cfl;
    std::vector<double> differences;
    for (const int steps : {4, 8, 16, 32}) {
        const Particles<2> implicit = run_block(models, duration, steps, true);
        const Particles<2> explicit_ = run_block(models, duration, steps, false);
        double worst = 0.0;
        for (int p = 0; p < implicit.size(); ++p)
            worst = std::max(worst, (implicit.x[static_cast<std::size_t>(p)] - explicit_.x[static_cast<std::size_t>(p)]).norm());
        differences.push_back(worst);
        UNSCOPED_INFO("steps " << steps << ": max |x_implicit - x_explicit| = " << worst);
    }
    // The block moves: the differences are not round-off.
    CHECK(differences[0] > 1e-6);
    for (std::size_t k = 1; k < differences.size(); ++k) {
        CAPTURE(k, differences[k - 1], differences[k]);
        CHECK(differences[k] < 0.7 * differences[k - 1]);
    }
    // First order: eight times smaller over three halvings, up to a margin.
    CHECK(differences.back() < differences.front() / 5.0);
}

TEST_CASE("implicit MPM: stable at 10 times the explicit CFL step, where the explicit step blows up")
{
    const auto model = lame_model<2>("stable-neo-hookean", 1e5, 2e5);
    const std::vector<const Model2d*> models{model.get()};
    const double g = 9.81;
    const double cfl = cfl_time_step(stretched_block(0.25), models, 0.1, 1.0);
    MpmStepSettings<2> settings;
    settings.time_step = 10.0 * cfl;
    settings.gravity = Eigen::Vector2d(0.0, -g);
    settings.walls = GridWalls<2>::box(Eigen::Vector2d::Zero(), Eigen::Vector2d::Ones(), GridCondition::separate);
    for (const bool implicit : {true, false}) {
        CAPTURE(implicit, settings.time_step);
        Particles<2> particles = stretched_block(0.25);
        SparseGrid<2> grid(0.1);
        const double start = total_energy(particles, models, g);
        double largest = start;
        bool finite = true;
        for (int n = 0; n < 40 && finite; ++n) {
            if (implicit)
                CHECK(implicit_step(particles, models, settings, grid, solve_with("projected-newton")).converged);
            else
                finite = explicit_step_stays_finite(particles, models, settings, grid);
            const double energy = total_energy(particles, models, g);
            finite = finite && std::isfinite(energy);
            if (finite)
                largest = std::max(largest, energy);
        }
        UNSCOPED_INFO((implicit ? "implicit" : "explicit") << ": largest energy / initial = " << largest / start
                                                            << (finite ? "" : ", not finite"));
        if (implicit) {
            CHECK((finite && largest <= start * (1.0 + 1e-9)));
            // It fell onto the floor and stayed above it (the floor's band is
            // two cells, so particles stop about a cell above y = 0).
            double lowest = 1.0;
            for (const auto& x : particles.x)
                lowest = std::min(lowest, x[1]);
            CHECK(lowest < stretched_block(0.25).x[0][1] - 0.02);
            CHECK(lowest > 0.0);
        }
        else
            CHECK((!finite || largest > 100.0 * start));
    }
}
