#include "sinew/problems/quasistatic/parts/scene_part.hpp"
#include "sinew/problems/quasistatic/parts/scene_reading.hpp"

#include "sinew/core/format_number.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <complex>

namespace sinew {
namespace {

/// A factor s moves a set by M(s) = I + s(M − I) (scene.hpp), whose
/// eigenvalues are 1 + s(λ − 1) over the eigenvalues λ of M: M(s) is singular
/// exactly where a real λ ≠ 1 gives 1 + s(λ − 1) = 0, s = 1/(1 − λ). Why the
/// factors [lowest, highest] reach such an s ("" when they do not); a load
/// step's s ∈ [0, 1] reaches it exactly when M has a real eigenvalue λ ≤ 0
/// (singular, a reflection, a flattening).
std::string blend_refusal(const Eigen::MatrixXd& M, double lowest, double highest)
{
    const double scale = std::max(1.0, M.cwiseAbs().maxCoeff());
    const Eigen::VectorXcd eigenvalues = M.eigenvalues();
    for (Eigen::Index i = 0; i < eigenvalues.size(); ++i) {
        const std::complex<double> lambda = eigenvalues[i];
        if (std::abs(lambda.imag()) > 1e-12 * scale)
            continue;
        const double mu = lambda.real() - 1.0;  // the eigenvalue of M(s) is 1 + s·μ
        const double at_lowest = 1.0 + lowest * mu, at_highest = 1.0 + highest * mu;
        const double round_off = 1e-12 * scale * std::max({1.0, std::abs(lowest), std::abs(highest)});
        if (at_lowest * at_highest <= 0.0 || std::abs(at_lowest) <= round_off || std::abs(at_highest) <= round_off)
            return "the map has the real eigenvalue " + format_number(lambda.real()) +
                   ": I + s(M - I) is singular at s = " + format_number(-1.0 / mu) + ", within the factors [" +
                   format_number(lowest) + ", " + format_number(highest) + "] it takes";
    }
    return "";
}

/// Set k's motion as a quantity a load factor scales.
ScaledQuantity motion_quantity(const JsonCursor& b, const std::string& name, const PrescribedMotion& m, size_t k,
                               int dimension)
{
    ScaledQuantity q;
    q.name = "boundary '" + name + "'";
    if (auto curve = b.find("curve"))
        q.curve = keyframes(*curve);
    q.set = [k, dimension](Scene& scene, double s0, double s1, double w) {
        const PrescribedMotion& motion = scene.motions[k];
        scene.problem->set_affine_map(static_cast<int>(k),
                                      (1.0 - w) * motion.map_at(s0, dimension) + w * motion.map_at(s1, dimension),
                                      (1.0 - w) * motion.translation_at(s0, dimension) +
                                          w * motion.translation_at(s1, dimension));
    };
    if (!m.rotation) {
        const Eigen::MatrixXd map = m.map;
        q.refusal = [map](double lowest, double highest) { return blend_refusal(map, lowest, highest); };
    }
    return q;
}

/// "boundary": Dirichlet sets, each a selection of nodes moved by a rigid
/// rotation or an affine map at load factor 1.
class BoundaryPart final : public ScenePart {
public:
    std::string key() const override { return "boundary"; }
    std::string doc() const override { return "Dirichlet sets: selected nodes held at rest or moved by a rotation or a map"; }
    std::string kind() const override { return "constraints"; }
    int stage() const override { return 40; }
    std::vector<SceneKey> keys() const override
    {
        return {{"[].name", "string", "", "boundary[i]", "the set's name in messages"},
                {"[].select", "selection", "", "", "the nodes of the set", true},
                {"[].rotation", "object", "{axis, angle_deg, center}", "", "x = R(θ)(X − c) + c + t at load factor 1"},
                {"[].map", "matrix", "I + s(M − I) regular for every factor s taken", "I", "x = M X + t at load factor 1"},
                {"[].translation", "vector", "", "0", "t (m)"},
                {"[].curve", "keyframes", "[[t, s], …], t increasing", "dynamics.load_curve",
                 "s(t) moving this set over time (a scene with dynamics)"}};
    }
    void read(const JsonCursor& list, SceneAssembly& assembly) const override
    {
        const DeclaredKeys declared(keys());
        Scene& scene = assembly.scene;
        const int dimension = static_cast<int>(scene.mesh.nodes.rows());
        for (size_t i = 0; i < list.size(); ++i) {
            const JsonCursor b = list[i];
            declared.expect_object(b, "[]");
            PrescribedMotion m = prescribed_motion(b, dimension);
            DirichletSet set;
            set.name = b.has("name") ? b.at("name").string() : "boundary[" + std::to_string(i) + "]";
            set.nodes = selected_nodes(b.at("select"), scene.mesh, assembly.tolerance);
            set.map = m.map_at(1.0, dimension);
            set.translation = m.translation_at(1.0, dimension);
            assembly.add_scaled(motion_quantity(b, set.name, m, assembly.dirichlet_sets.size(), dimension),
                                b.has("curve") ? b.at("curve") : b.has("map") ? b.at("map") : b);
            assembly.dirichlet_sets.push_back(std::move(set));
            scene.motions.push_back(std::move(m));
        }
    }
};

const SceneRegistration<BoundaryPart> boundary_part;

} // namespace
} // namespace sinew
