// The inextensibility constraint sets (seed 004 §4.1): a₀ᵀ C a₀ = 1 per
// element (FiberInextensibility) on tets, 2D triangles and membranes, and
// fixed segment lengths along threads (ThreadLengths). Their derivatives go
// through the library's shared checks (check_derivatives, taylor_test) inside
// a QuasistaticProblem with an elastic potential, in every deformation regime.
#include "sinew/core/input_error.hpp"
#include "sinew/energies/constraints/fiber_inextensibility.hpp"
#include "sinew/energies/constraints/thread_lengths.hpp"
#include "sinew/energies/constraints/weak_fiber_inextensibility.hpp"
#include "sinew/energies/potentials/elastic_potential.hpp"
#include "sinew/energies/potentials/element_rest_shape.hpp"
#include "sinew/problems/derivative_check.hpp"
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/problems/taylor_test.hpp"

#include "energies/deformation_regimes.hpp"
#include "potentials/test_meshes.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

using namespace sinew;
using namespace sinew::test;

namespace {

constexpr double kH = 0.25;  // element size of the test meshes

/// The configurations the derivative checks visit.
enum class Pose { near_rest, large_stretch, compression, rotated, near_inversion };

std::vector<Pose> all_poses()
{
    return {Pose::near_rest, Pose::large_stretch, Pose::compression, Pose::rotated, Pose::near_inversion};
}

std::string pose_name(Pose pose)
{
    switch (pose) {
    case Pose::near_rest: return "near rest";
    case Pose::large_stretch: return "large stretch x = 1.8 X";
    case Pose::compression: return "compression x = 0.6 X";
    case Pose::rotated: return "rotated";
    case Pose::near_inversion: return "near inversion";
    }
    return "?";
}

Eigen::MatrixXd random_rotation_of_dimension(int dimension, std::mt19937& rng)
{
    if (dimension == 3)
        return random_rotation<3>(rng);
    return random_rotation<2>(rng);
}

/// Node-major positions of `mesh` in `pose`, with a small random jitter:
/// x = A X + noise (A = I, 1.8 I, 0.6 I or a random rotation); near inversion
/// node 0 of a random element is moved to 5% of its rest distance from the
/// opposite face (edge for triangles).
Eigen::VectorXd posed(const Mesh& mesh, Pose pose, std::mt19937& rng)
{
    const int d = static_cast<int>(mesh.nodes.rows());
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    Eigen::MatrixXd A = Eigen::MatrixXd::Identity(d, d);
    double jitter = 0.02 * kH;
    switch (pose) {
    case Pose::near_rest: break;
    case Pose::large_stretch: A *= 1.8; break;
    case Pose::compression: A *= 0.6; break;
    case Pose::rotated: A = random_rotation_of_dimension(d, rng); break;
    case Pose::near_inversion: jitter = 0.002 * kH; break;
    }
    Eigen::MatrixXd x = A * mesh.nodes;
    for (int i = 0; i < x.size(); ++i)
        x.data()[i] += jitter * u11(rng);
    if (pose == Pose::near_inversion) {
        const int e = std::uniform_int_distribution<int>(0, mesh.num_elements() - 1)(rng);
        const int n = static_cast<int>(mesh.elements.rows());
        Eigen::VectorXd opposite = Eigen::VectorXd::Zero(d);
        for (int a = 1; a < n; ++a)
            opposite += mesh.nodes.col(mesh.elements(a, e)) / (n - 1);
        const int moved = mesh.elements(0, e);
        x.col(moved) = opposite + 0.05 * (mesh.nodes.col(moved) - opposite);
    }
    return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
}

/// One random direction per column, standard-normal components (not normalized: the set does that).
Eigen::MatrixXd random_fibers(int rows, int count, std::mt19937& rng)
{
    std::normal_distribution<double> normal;
    Eigen::MatrixXd fibers(rows, count);
    for (int i = 0; i < fibers.size(); ++i)
        fibers.data()[i] = normal(rng);
    return fibers;
}

/// A soft elastic potential of the mesh's kind, so that the constraint
/// curvature is not lost beside the elastic one in the Hessian check.
std::shared_ptr<TotalPotential> soft_elastic(const Mesh& mesh)
{
    ElementModel model;
    switch (mesh.kind) {
    case ElementKind::tetrahedron:
        model = make_element_model(mesh.kind, "stable-neo-hookean", {{"mu", 10.0}, {"lambda", 40.0}});
        break;
    case ElementKind::triangle_2d:
        model = make_element_model(mesh.kind, "qr-anisotropic", {{"mu", 10.0}, {"lambda", 40.0}, {"kx", 10.0}});
        break;
    case ElementKind::triangle_3d:
        model = make_element_model(mesh.kind, "codim-corotated", {{"mu", 10.0}, {"lambda", 5.0}});
        break;
    }
    auto elastic = std::make_shared<ElasticPotential>(mesh, std::vector<ElementModel>{model});
    return std::make_shared<TotalPotential>(std::vector<std::shared_ptr<Potential>>{elastic});
}

/// Every element but each third one carries a random fiber.
std::shared_ptr<FiberInextensibility> fibers_on(const Mesh& mesh, std::mt19937& rng)
{
    std::vector<int> listed;
    for (int e = 0; e < mesh.num_elements(); ++e)
        if (e % 3 != 2)
            listed.push_back(e);
    return std::make_shared<FiberInextensibility>(
        mesh, listed, random_fibers(material_dimension(mesh.kind), static_cast<int>(listed.size()), rng));
}

/// The shared checks at x: entrywise central differences (report.passed(1e-5))
/// and the Taylor test, with the objective in ∇²L (σ = 1) and without it
/// (σ = 0, where ∇²L is the constraint curvature Σλᵢ∇²cᵢ alone).
void check_nlp(QuasistaticProblem& nlp, const Eigen::VectorXd& x)
{
    REQUIRE(x.allFinite());
    REQUIRE(std::isfinite(nlp.objective(x)));
    for (double sigma : {1.0, 0.0}) {
        CAPTURE(sigma);
        DerivativeCheckOptions entrywise_options;
        entrywise_options.sigma = sigma;
        const DerivativeCheckReport entrywise = check_derivatives(nlp, x, entrywise_options);
        CAPTURE(entrywise.to_text());
        CHECK(entrywise.passed(1e-5));
        CHECK(entrywise.jacobian.entries_compared > 0);
        CHECK(entrywise.hessian.entries_compared > 0);
        TaylorOptions taylor_options;
        taylor_options.sigma = sigma;
        const TaylorReport taylor = taylor_test(nlp, x, taylor_options);
        CAPTURE(taylor.to_text());
        CHECK(taylor.passed());
        CHECK(taylor.jacobian.tested);
    }
}

/// The sweep: every pose, two random points each, the set alone in the NLP
/// (no Dirichlet set: every coordinate is a variable).
void check_every_pose(const Mesh& mesh, const std::shared_ptr<ConstraintSet>& set, std::mt19937& rng)
{
    QuasistaticOptions options;
    options.constraints = {set};
    QuasistaticProblem nlp(mesh.nodes, soft_elastic(mesh), {}, options);
    REQUIRE(nlp.num_constraints() == set->num_constraints());
    for (Pose pose : all_poses())
        for (int point = 0; point < 2; ++point) {
            CAPTURE(pose_name(pose), point);
            check_nlp(nlp, posed(mesh, pose, rng));
        }
}

Eigen::VectorXd values_of(ConstraintSet& set, const Eigen::VectorXd& x)
{
    Eigen::VectorXd c(set.num_constraints());
    set.values(x, c);
    return c;
}

/// Σλᵢ∇²cᵢ of a set as a dense symmetric matrix (repeated entries summed).
Eigen::MatrixXd dense_curvature(ConstraintSet& set, const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                                Projection projection)
{
    const SparsityPattern& pattern = set.hessian_pattern();
    Eigen::VectorXd values(pattern.nonzeros());
    set.hessian_values(x, lambda, projection, values);
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(x.size(), x.size());
    for (int k = 0; k < pattern.nonzeros(); ++k) {
        H(pattern.rows[k], pattern.cols[k]) += values[k];
        if (pattern.rows[k] != pattern.cols[k])
            H(pattern.cols[k], pattern.rows[k]) += values[k];
    }
    return H;
}

/// x = X + (s − 1)(d·X) d: stretch by s along the unit direction d, nothing across.
Eigen::VectorXd stretched_along(const Mesh& mesh, const Eigen::VectorXd& d, double s)
{
    Eigen::MatrixXd x = mesh.nodes;
    for (int i = 0; i < mesh.num_nodes(); ++i)
        x.col(i) += (s - 1.0) * d.dot(mesh.nodes.col(i)) * d;
    return Eigen::Map<const Eigen::VectorXd>(x.data(), x.size());
}

std::vector<int> all_elements(const Mesh& mesh)
{
    std::vector<int> elements(mesh.num_elements());
    for (int e = 0; e < mesh.num_elements(); ++e)
        elements[e] = e;
    return elements;
}

/// Threads along mesh edges of the 2 × 2 × 2 box: a grid line along x, a
/// bent line up the side, and the main diagonal (an edge of every Kuhn cube).
std::vector<std::vector<int>> box_threads()
{
    return {{grid_node(0, 1, 1, 2, 2), grid_node(1, 1, 1, 2, 2), grid_node(2, 1, 1, 2, 2)},
            {grid_node(0, 0, 0, 2, 2), grid_node(0, 0, 1, 2, 2), grid_node(0, 1, 1, 2, 2), grid_node(0, 1, 2, 2, 2)},
            {grid_node(0, 0, 0, 2, 2), grid_node(1, 1, 1, 2, 2), grid_node(2, 2, 2, 2, 2)}};
}

} // namespace

TEST_CASE("fiber inextensibility on tets passes the shared derivative checks in every regime",
          "[inextensibility]")
{
    std::mt19937 rng(41);
    const Mesh mesh = box_of_tets(2, 2, 2, kH);
    check_every_pose(mesh, fibers_on(mesh, rng), rng);
}

TEST_CASE("fiber inextensibility on 2D triangles passes the shared derivative checks in every regime",
          "[inextensibility]")
{
    std::mt19937 rng(42);
    const Mesh mesh = rectangle_of_triangles(3, 3, kH);
    check_every_pose(mesh, fibers_on(mesh, rng), rng);
}

TEST_CASE("fiber inextensibility on triangles in 3D passes the shared derivative checks in every regime",
          "[inextensibility]")
{
    std::mt19937 rng(43);
    const Mesh mesh = sheet_of_triangles(3, 3, kH, random_rotation<3>(rng));
    check_every_pose(mesh, fibers_on(mesh, rng), rng);
}

TEST_CASE("thread lengths pass the shared derivative checks in every regime, in 3D and 2D", "[inextensibility]")
{
    std::mt19937 rng(44);
    SECTION("threads through a box of tets")
    {
        const Mesh mesh = box_of_tets(2, 2, 2, kH);
        auto threads = std::make_shared<ThreadLengths>(mesh.num_nodes(), 3, rest_coordinates(mesh), box_threads());
        check_every_pose(mesh, threads, rng);
    }
    SECTION("threads through a rectangle of triangles, one of them closed")
    {
        const Mesh mesh = rectangle_of_triangles(3, 3, kH);
        const std::vector<std::vector<int>> threads{
            {grid_node(0, 1, 0, 3, 3), grid_node(1, 1, 0, 3, 3), grid_node(2, 1, 0, 3, 3), grid_node(3, 1, 0, 3, 3)},
            {grid_node(1, 2, 0, 3, 3), grid_node(2, 2, 0, 3, 3), grid_node(2, 3, 0, 3, 3), grid_node(1, 3, 0, 3, 3),
             grid_node(1, 2, 0, 3, 3)}};
        check_every_pose(mesh, std::make_shared<ThreadLengths>(mesh.num_nodes(), 2, rest_coordinates(mesh), threads),
                         rng);
    }
}

TEST_CASE("inextensibility sets beside Dirichlet conditions pass the derivative checks for both strategies",
          "[inextensibility]")
{
    std::mt19937 rng(45);
    const Mesh mesh = box_of_tets(2, 2, 2, kH);
    std::vector<int> bottom;
    for (int j = 0; j <= 2; ++j)
        for (int i = 0; i <= 2; ++i)
            bottom.push_back(grid_node(i, j, 0, 2, 2));
    for (DirichletStrategy strategy : {DirichletStrategy::eliminate, DirichletStrategy::equality_constraints}) {
        CAPTURE(to_string(strategy));
        QuasistaticOptions options;
        options.dirichlet = strategy;
        auto threads = std::make_shared<ThreadLengths>(mesh.num_nodes(), 3, rest_coordinates(mesh), box_threads());
        options.constraints = {fibers_on(mesh, rng), threads};
        QuasistaticProblem nlp(mesh.nodes, soft_elastic(mesh), {fixed_at_rest("bottom", bottom, 3)}, options);
        const Eigen::VectorXd x = nlp.variables_of(posed(mesh, Pose::near_rest, rng));
        check_nlp(nlp, x);
    }
}

TEST_CASE("fiber inextensibility is zero at rest and s^2 - 1 under a stretch s along the fiber", "[inextensibility]")
{
    std::mt19937 rng(46);
    SECTION("tets")
    {
        const Mesh mesh = box_of_tets(2, 2, 2, kH);
        const Eigen::MatrixXd random = random_fibers(3, mesh.num_elements(), rng);
        FiberInextensibility set(mesh, all_elements(mesh), random);
        CHECK(values_of(set, rest_coordinates(mesh)).cwiseAbs().maxCoeff() <= 1e-12);
        for (int k = 0; k < set.num_constraints(); ++k)
            CHECK(set.fiber(k).isApprox(random.col(k).normalized(), 1e-14));
        const Eigen::Vector3d d = random_fibers(3, 1, rng).col(0).normalized();
        FiberInextensibility along(mesh, all_elements(mesh), d.replicate(1, mesh.num_elements()));
        for (double s : {0.5, 1.0, 1.3, 2.0}) {
            CAPTURE(s);
            const Eigen::VectorXd c = values_of(along, stretched_along(mesh, d, s));
            CHECK((c.array() - (s * s - 1.0)).abs().maxCoeff() <= 1e-12);
        }
        // Across the fiber the stretch does not count.
        const Eigen::Vector3d across = d.unitOrthogonal();
        CHECK(values_of(along, stretched_along(mesh, across, 1.7)).cwiseAbs().maxCoeff() <= 1e-12);
    }
    SECTION("2D triangles")
    {
        const Mesh mesh = rectangle_of_triangles(3, 3, kH);
        FiberInextensibility set(mesh, all_elements(mesh), random_fibers(2, mesh.num_elements(), rng));
        CHECK(values_of(set, rest_coordinates(mesh)).cwiseAbs().maxCoeff() <= 1e-12);
        const Eigen::Vector2d d = random_fibers(2, 1, rng).col(0).normalized();
        FiberInextensibility along(mesh, all_elements(mesh), d.replicate(1, mesh.num_elements()));
        for (double s : {0.5, 1.0, 1.3, 2.0}) {
            CAPTURE(s);
            const Eigen::VectorXd c = values_of(along, stretched_along(mesh, d, s));
            CHECK((c.array() - (s * s - 1.0)).abs().maxCoeff() <= 1e-12);
        }
    }
    SECTION("triangles in 3D, fibers given in each element's rest frame or in space")
    {
        const Eigen::Matrix3d R = random_rotation<3>(rng);
        const Mesh mesh = sheet_of_triangles(3, 3, kH, R);
        FiberInextensibility set(mesh, all_elements(mesh), random_fibers(2, mesh.num_elements(), rng));
        CHECK(values_of(set, rest_coordinates(mesh)).cwiseAbs().maxCoeff() <= 1e-12);
        // d in the sheet's plane; in element e's frame E_e it is E_eᵀd.
        const Eigen::Vector3d d = R * Eigen::Vector3d(std::cos(0.7), std::sin(0.7), 0.0);
        Eigen::MatrixXd in_frames(2, mesh.num_elements());
        for (int e = 0; e < mesh.num_elements(); ++e) {
            const Eigen::Matrix<double, 3, 2> frame = membrane_rest_frame(
                mesh.nodes.col(mesh.elements(0, e)), mesh.nodes.col(mesh.elements(1, e)), mesh.nodes.col(mesh.elements(2, e)));
            in_frames.col(e) = frame.transpose() * d;
        }
        FiberInextensibility material(mesh, all_elements(mesh), in_frames);
        // A spatial fiber with an out-of-plane part: only its in-plane part counts.
        const Eigen::Vector3d normal = R.col(2);
        const Eigen::MatrixXd tilted = (2.0 * d + 0.5 * normal).replicate(1, mesh.num_elements());
        FiberInextensibility spatial(mesh, all_elements(mesh), tilted);
        for (int k = 0; k < material.num_constraints(); ++k)
            CHECK(spatial.fiber(k).isApprox(material.fiber(k), 1e-12));
        for (double s : {0.5, 1.0, 1.3, 2.0}) {
            CAPTURE(s);
            const Eigen::VectorXd x = stretched_along(mesh, d, s);
            CHECK((values_of(material, x).array() - (s * s - 1.0)).abs().maxCoeff() <= 1e-12);
            CHECK((values_of(spatial, x).array() - (s * s - 1.0)).abs().maxCoeff() <= 1e-12);
        }
    }
}

TEST_CASE("thread lengths are zero at rest and s^2 - 1 under a uniform scaling s whatever the segment length",
          "[inextensibility]")
{
    const Mesh mesh = box_of_tets(2, 2, 2, kH);
    ThreadLengths set(mesh.num_nodes(), 3, rest_coordinates(mesh), box_threads());
    CHECK(set.num_constraints() == 2 + 3 + 2);
    CHECK(values_of(set, rest_coordinates(mesh)).cwiseAbs().maxCoeff() <= 1e-15);
    // c = |x_j − x_i|²/L² − 1: dimensionless, the same on segments of lengths h and √3 h.
    const Eigen::VectorXd c = values_of(set, 1.5 * rest_coordinates(mesh));
    for (int k = 0; k < set.num_constraints(); ++k)
        CHECK(c[k] == Approx(1.5 * 1.5 - 1.0).epsilon(1e-13));
    CHECK(set.rest_lengths()[0] == Approx(kH));
    CHECK(set.rest_lengths()[5] == Approx(std::sqrt(3.0) * kH));
}

TEST_CASE("projected constraint curvature is zero for negative multipliers and exact for positive ones",
          "[inextensibility]")
{
    std::mt19937 rng(47);
    std::uniform_real_distribution<double> u(0.1, 2.0);
    const Mesh tets = box_of_tets(2, 2, 2, kH);
    const Mesh plane = rectangle_of_triangles(3, 3, kH);
    const Mesh sheet = sheet_of_triangles(3, 3, kH, random_rotation<3>(rng));
    std::vector<std::pair<std::string, std::pair<std::shared_ptr<ConstraintSet>, Eigen::VectorXd>>> cases{
        {"tets", {fibers_on(tets, rng), posed(tets, Pose::large_stretch, rng)}},
        {"2D triangles", {fibers_on(plane, rng), posed(plane, Pose::rotated, rng)}},
        {"triangles in 3D", {fibers_on(sheet, rng), posed(sheet, Pose::compression, rng)}},
        {"threads", {std::make_shared<ThreadLengths>(tets.num_nodes(), 3, rest_coordinates(tets), box_threads()),
                     posed(tets, Pose::near_inversion, rng)}},
    };
    for (auto& [label, set_and_x] : cases) {
        CAPTURE(label);
        ConstraintSet& set = *set_and_x.first;
        const Eigen::VectorXd& x = set_and_x.second;
        const int m = set.num_constraints();
        Eigen::VectorXd positive(m);
        for (int k = 0; k < m; ++k)
            positive[k] = u(rng);
        const Eigen::MatrixXd exact = dense_curvature(set, x, positive, Projection::none);
        REQUIRE(exact.cwiseAbs().maxCoeff() > 0.0);
        CHECK(dense_curvature(set, x, positive, Projection::clamp) == exact);
        // With λ > 0 every term is PSD, hence so is the sum.
        CHECK(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(exact).eigenvalues().minCoeff() >=
              -1e-10 * exact.cwiseAbs().maxCoeff());
        // λ < 0: λ∇²c is negative semidefinite, its projection zero.
        CHECK(dense_curvature(set, x, -positive, Projection::clamp).cwiseAbs().maxCoeff() == 0.0);
        CHECK(dense_curvature(set, x, -positive, Projection::none) == -exact);
        // Mixed signs: only the positive terms remain.
        Eigen::VectorXd mixed = positive, kept = positive;
        for (int k = 0; k < m; k += 2) {
            mixed[k] = -positive[k];
            kept[k] = 0.0;
        }
        CHECK((dense_curvature(set, x, mixed, Projection::clamp) - dense_curvature(set, x, kept, Projection::none))
                  .cwiseAbs()
                  .maxCoeff() <= 1e-12 * exact.cwiseAbs().maxCoeff());
    }
}

TEST_CASE("fiber inextensibility patterns: one Jacobian row per listed element, lower-triangle Hessian",
          "[inextensibility]")
{
    std::mt19937 rng(48);
    const Mesh mesh = box_of_tets(1, 1, 1, kH);
    FiberInextensibility set(mesh, {4, 1}, random_fibers(3, 2, rng));
    const SparsityPattern& J = set.jacobian_pattern();
    REQUIRE(J.nonzeros() == 2 * 4 * 3);
    for (int entry = 0; entry < J.nonzeros(); ++entry) {
        const int k = entry / 12;
        const int node = mesh.elements((entry % 12) / 3, set.elements()[k]);
        CHECK(J.rows[entry] == k);
        CHECK(J.cols[entry] == 3 * node + entry % 3);
    }
    const SparsityPattern& H = set.hessian_pattern();
    CHECK(H.nonzeros() == 2 * 10 * 3);
    for (int entry = 0; entry < H.nonzeros(); ++entry) {
        CHECK(H.rows[entry] >= H.cols[entry]);
        CHECK(H.rows[entry] % 3 == H.cols[entry] % 3);  // ∇²c = 2 (w wᵀ) ⊗ I couples equal coordinates only
    }
    // The weights sum to zero: a translation does not change F.
    for (int k = 0; k < set.num_constraints(); ++k)
        CHECK(std::abs(set.node_weights(k).sum()) <= 1e-12 * set.node_weights(k).cwiseAbs().maxCoeff());
}

TEST_CASE("fiber inextensibility rejects bad input with an InputError", "[inextensibility]")
{
    using Catch::Matchers::Contains;
    const Mesh tets = box_of_tets(1, 1, 1, kH);
    const Eigen::Vector3d x_axis(1.0, 0.0, 0.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(FiberInextensibility(tets, {6}, x_axis), Contains("listed element 0 is 6, outside [0, 6)"));
    CHECK_THROWS_WITH(FiberInextensibility(tets, {-1}, x_axis), Contains("outside [0, 6)"));
    CHECK_THROWS_WITH(FiberInextensibility(tets, {2}, Eigen::Vector3d::Zero()), Contains("fiber is zero"));
    CHECK_THROWS_WITH(FiberInextensibility(tets, {2}, Eigen::Vector3d(1.0, nan, 0.0)), Contains("not finite"));
    CHECK_THROWS_WITH(FiberInextensibility(tets, {2}, Eigen::Vector3d(inf, 0.0, 0.0)), Contains("not finite"));
    CHECK_THROWS_WITH(FiberInextensibility(tets, {2, 3}, x_axis), Contains("2 elements listed but 1 fibers given"));
    CHECK_THROWS_WITH(FiberInextensibility(tets, {2}, Eigen::Vector2d(1.0, 0.0)), Contains("not 2"));
    CHECK_THROWS_WITH(FiberInextensibility(tets, {2, 2}, x_axis.replicate(1, 2)), Contains("listed twice"));
    CHECK_THROWS_AS(FiberInextensibility(tets, {2}, Eigen::Vector3d::Zero()), InputError);

    Mesh flat = tets;  // node 7 onto node 0's position: the tets through the main diagonal lose their volume
    flat.nodes.col(grid_node(1, 1, 1, 1, 1)) = flat.nodes.col(grid_node(0, 0, 0, 1, 1));
    CHECK_THROWS_AS(FiberInextensibility(flat, {0}, x_axis), InputError);
    CHECK_THROWS_WITH(FiberInextensibility(flat, {0}, x_axis),
                      Contains("fiber inextensibility: ") && Contains("degenerate"));

    const Mesh sheet = sheet_of_triangles(1, 1, kH, Eigen::Matrix3d::Identity());
    CHECK_THROWS_WITH(FiberInextensibility(sheet, {0}, Eigen::Vector3d(0.0, 0.0, 1.0)),
                      Contains("fiber is zero or normal to the rest plane"));
    CHECK_THROWS_WITH(FiberInextensibility(sheet, {0}, Eigen::Vector4d(1.0, 0.0, 0.0, 0.0)),
                      Contains("2 or 3 components"));
    const Mesh plane = rectangle_of_triangles(1, 1, kH);
    CHECK_THROWS_WITH(FiberInextensibility(plane, {0}, x_axis), Contains("2 components, not 3"));
    CHECK_NOTHROW(FiberInextensibility(plane, {}, Eigen::MatrixXd(2, 0)));
}

TEST_CASE("thread lengths reject bad input with an InputError", "[inextensibility]")
{
    using Catch::Matchers::Contains;
    const Mesh mesh = box_of_tets(1, 1, 1, kH);
    const Eigen::VectorXd X = rest_coordinates(mesh);
    const int n = mesh.num_nodes();
    CHECK_THROWS_WITH(ThreadLengths(n, 3, X, {{0, 1, 8}}),
                      Contains("polyline 0, position 2: node 8 is outside [0, 8)"));
    CHECK_THROWS_WITH(ThreadLengths(n, 3, X, {{0, 1}, {-1, 2}}), Contains("polyline 1, position 0"));
    CHECK_THROWS_WITH(ThreadLengths(n, 3, X, {{0, 1, 1, 3}}), Contains("node 1 repeats the node before it"));
    CHECK_THROWS_WITH(ThreadLengths(n, 3, X, {{2}}), Contains("at least 2"));
    CHECK_THROWS_WITH(ThreadLengths(n, 3, X, {{0, 1, 3}, {3, 1}}), Contains("listed twice"));
    CHECK_THROWS_WITH(ThreadLengths(n, 3, X.head(6), {{0, 1}}), Contains("6 rest coordinates for 8 nodes"));
    CHECK_THROWS_WITH(ThreadLengths(n, 4, X, {{0, 1}}), Contains("expected 2 or 3"));
    Eigen::VectorXd coincident = X;
    coincident.segment<3>(3) = coincident.segment<3>(0);
    CHECK_THROWS_WITH(ThreadLengths(n, 3, coincident, {{0, 1}}), Contains("zero rest length"));
    Eigen::VectorXd not_finite = X;
    not_finite[4] = std::numeric_limits<double>::quiet_NaN();
    CHECK_THROWS_AS(ThreadLengths(n, 3, not_finite, {{0, 1}}), InputError);
    CHECK_NOTHROW(ThreadLengths(n, 3, X, {{0, 1, 3, 2, 0}}));  // a closed thread
}

namespace {

/// Every element, one random fiber each, in weak form on a `cells` grid.
std::shared_ptr<WeakFiberInextensibility> weak_fibers_on(const Mesh& mesh, const Eigen::VectorXi& cells,
                                                        std::mt19937& rng)
{
    const std::vector<int> listed = all_elements(mesh);
    return std::make_shared<WeakFiberInextensibility>(
        mesh, listed, random_fibers(material_dimension(mesh.kind), static_cast<int>(listed.size()), rng), cells);
}

/// The numerical rank of the dense Jacobian of `set` at x.
int jacobian_rank(ConstraintSet& set, const Eigen::VectorXd& x)
{
    Eigen::VectorXd values(set.jacobian_pattern().nonzeros());
    set.jacobian_values(x, values);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(set.num_constraints(), x.size());
    for (int k = 0; k < values.size(); ++k)
        J(set.jacobian_pattern().rows[k], set.jacobian_pattern().cols[k]) += values[k];
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
    qr.setThreshold(1e-10);
    return static_cast<int>(qr.rank());
}

} // namespace

TEST_CASE("weak-form fiber inextensibility passes the shared derivative checks in every regime",
          "[inextensibility]")
{
    std::mt19937 rng(47);
    const Mesh tets = box_of_tets(2, 2, 2, kH);
    check_every_pose(tets, weak_fibers_on(tets, Eigen::Vector3i(2, 1, 1), rng), rng);
    const Mesh plate = rectangle_of_triangles(4, 4, kH);
    check_every_pose(plate, weak_fibers_on(plate, Eigen::Vector2i(2, 2), rng), rng);
}

TEST_CASE("weak-form fiber inextensibility is the volume-weighted mean of c_e per grid cell and has full row rank "
          "where the per-element form does not",
          "[inextensibility]")
{
    std::mt19937 rng(48);
    const Mesh mesh = box_of_tets(4, 4, 4, kH);
    const std::vector<int> listed = all_elements(mesh);
    const Eigen::MatrixXd fibers = random_fibers(3, static_cast<int>(listed.size()), rng);
    FiberInextensibility per_element(mesh, listed, fibers);
    WeakFiberInextensibility weak(mesh, listed, fibers, Eigen::Vector3i(2, 2, 2));
    REQUIRE(weak.num_constraints() == 8);  // 2×2×2 cells, each holding 8 hex cells of 6 tets
    const Eigen::VectorXd x = posed(mesh, all_poses()[1], rng);
    // c_z = Σ_{e∈z} V_e c_e / Σ_{e∈z} V_e: with equal V_e = h³/6, the mean of
    // the cell's c_e; a uniform stretch s along every fiber gives s² − 1 in each.
    const Eigen::VectorXd weak_values = values_of(weak, x), element_values = values_of(per_element, x);
    Eigen::VectorXd sums = Eigen::VectorXd::Zero(8), counts = Eigen::VectorXd::Zero(8);
    for (size_t k = 0; k < listed.size(); ++k) {
        sums[weak.row_of_element()[k]] += element_values[static_cast<Eigen::Index>(k)];
        counts[weak.row_of_element()[k]] += 1.0;
    }
    for (int z = 0; z < 8; ++z)
        CHECK(weak_values[z] == Approx(sums[z] / counts[z]).epsilon(1e-12));
    const Eigen::VectorXd stretched = values_of(weak, 1.2 * rest_coordinates(mesh));
    CHECK((stretched.array() - (1.2 * 1.2 - 1.0)).abs().maxCoeff() <= 1e-12);
    // 384 per-element rows on 125 nodes (375 coordinates): rank-deficient;
    // the 8 weak rows are independent.
    CHECK(per_element.num_constraints() == 384);
    CHECK(jacobian_rank(per_element, x) < per_element.num_constraints());
    CHECK(jacobian_rank(weak, x) == weak.num_constraints());
}

TEST_CASE("weak-form fiber inextensibility rejects a grid with a zero cell count", "[inextensibility]")
{
    std::mt19937 rng(49);
    const Mesh mesh = box_of_tets(1, 1, 1, kH);
    CHECK_THROWS_AS(weak_fibers_on(mesh, Eigen::Vector3i(1, 0, 1), rng), InputError);
    CHECK_THROWS_AS(weak_fibers_on(mesh, Eigen::Vector2i(1, 1), rng), InputError);
}

TEST_CASE("weak-form fiber inextensibility rejects a grid cell that holds no element and spans the listed elements",
          "[inextensibility]")
{
    using Catch::Matchers::Contains;
    std::mt19937 rng(50);
    const Mesh mesh = box_of_tets(4, 4, 1, kH);
    // An L of elements: the hex cells with x or y in the first half; the
    // 2 × 2 grid over them has its corner cell (1, 1, 0) empty.
    std::vector<int> l_shape, corner;
    for (int e = 0; e < mesh.num_elements(); ++e) {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int a = 0; a < 4; ++a)
            centroid += mesh.nodes.col(mesh.elements(a, e)) / 4.0;
        const bool low_x = centroid.x() < 2 * kH, low_y = centroid.y() < 2 * kH;
        if (low_x || low_y)
            l_shape.push_back(e);
        if (low_x && low_y)
            corner.push_back(e);
    }
    const auto fibers = [&](size_t count) { return random_fibers(3, static_cast<int>(count), rng); };
    CHECK_THROWS_WITH(WeakFiberInextensibility(mesh, l_shape, fibers(l_shape.size()), Eigen::Vector3i(2, 2, 1)),
                      Contains("cell (1, 1, 0) of the 2 × 2 × 1 grid") && Contains("holds no element"));
    // The grid spans the listed elements, not the mesh: the corner alone fills 2 × 2 cells.
    WeakFiberInextensibility weak(mesh, corner, fibers(corner.size()), Eigen::Vector3i(2, 2, 1));
    CHECK(weak.num_constraints() == 4);
}
