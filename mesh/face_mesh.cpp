#include "sinew/mesh/face_mesh.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/mesh/face_geometry.hpp"
#include "sinew/mesh/face_skull.hpp"
#include "sinew/mesh/tetrahedralize_surface.hpp"
#include "sinew/mesh/triangle_surface.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace sinew {
namespace {

constexpr const char* kSource = "face generator";
/// Muscles lie in the outer part of the tissue, w ≥ this (w = 0 inner, 1 outer surface).
constexpr double kMuscleDepth = 0.3;
constexpr int kMinTets = 1000;
constexpr int kMaxTets = 2000000;
constexpr int kMinLandmarks = 40;
constexpr int kMinMuscleElements = 4;
/// Accepted |tets/target − 1| before the volume bound is recalibrated.
constexpr double kTetCountSlack = 0.25;

void check_shape(const FaceShape& s)
{
    const auto positive = [](double value, const char* name) {
        if (!(value > 0.0) || !std::isfinite(value))
            throw InputError(std::string(kSource) + ": " + name + " must be positive and finite");
    };
    positive(s.a, "a");
    positive(s.b, "b");
    positive(s.c, "c");
    positive(s.thickness, "thickness");
    positive(s.mouth_half_width, "mouth_half_width");
    positive(s.mouth_half_height, "mouth_half_height");
    if (!(s.rho > 0.0 && s.rho < 1.0))
        throw InputError(std::string(kSource) + ": rho must be in (0, 1)");
    if (!(s.skull_gap >= 0.0 && s.skull_gap <= s.thickness))
        throw InputError(std::string(kSource) + ": skull_gap must be in [0, thickness]");
    if (!(s.thickness < 0.5 * s.c))
        throw InputError(std::string(kSource) + ": thickness must be below half the depth c");
    FaceGeometry g{s};
    for (const double x : {-s.mouth_half_width, s.mouth_half_width})
        for (const double y : {s.mouth_y - s.mouth_half_height, s.mouth_y + s.mouth_half_height})
            if (!g.inside_face(x, y) || !std::isfinite(s.mouth_y))
                throw InputError(std::string(kSource) + ": the mouth does not fit inside the face");
    if (s.target_tets < kMinTets || s.target_tets > kMaxTets)
        throw InputError(std::string(kSource) + ": target_tets " + std::to_string(s.target_tets) + " is outside [" +
                         std::to_string(kMinTets) + ", " + std::to_string(kMaxTets) + "]");
}

/// A structured grid of cells over the trimmed ellipse: the square
/// (u, v) ∈ [−1, 1]² mapped onto the disc by x = ρa u √(1 − v²/2),
/// y = ρb v √(1 − u²/2) (the square's edges onto the ellipse), so the rim is
/// smooth. Cells whose centre falls in the mouth are dropped, then cells are
/// added back where two kept cells meet at a corner only, so that the
/// region's boundary is a manifold.
struct CellGrid {
    int nu = 0, nv = 0;
    double rho_a = 0.0, rho_b = 0.0;
    std::vector<char> kept;

    bool at(int i, int j) const { return i >= 0 && j >= 0 && i < nu && j < nv && kept[i + nu * j]; }
    /// (x, y) of grid point (i, j); half-integer indices give cell centres.
    Eigen::Vector2d xy(double i, double j) const
    {
        const double u = -1.0 + 2.0 * i / nu, v = -1.0 + 2.0 * j / nv;
        return {rho_a * u * std::sqrt(1.0 - 0.5 * v * v), rho_b * v * std::sqrt(1.0 - 0.5 * u * u)};
    }
};

CellGrid cell_grid(const FaceGeometry& g, double spacing)
{
    const FaceShape& s = g.shape;
    CellGrid grid;
    grid.rho_a = s.rho * s.a;
    grid.rho_b = s.rho * s.b;
    // The map stretches the square's middle lines by π/(2√2)·(…) at most ~1.1: spacing on the ellipse ≈ that of the square.
    grid.nu = std::max(4, static_cast<int>(std::ceil(2.0 * grid.rho_a / spacing)));
    grid.nv = std::max(4, static_cast<int>(std::ceil(2.0 * grid.rho_b / spacing)));
    grid.kept.assign(static_cast<std::size_t>(grid.nu) * grid.nv, 0);
    for (int j = 0; j < grid.nv; ++j)
        for (int i = 0; i < grid.nu; ++i) {
            const Eigen::Vector2d centre = grid.xy(i + 0.5, j + 0.5);
            grid.kept[i + grid.nu * j] = !g.inside_mouth(centre.x(), centre.y());
        }
    for (bool changed = true; changed;) {
        changed = false;
        for (int j = 0; j + 1 < grid.nv; ++j)
            for (int i = 0; i + 1 < grid.nu; ++i) {
                const bool a = grid.at(i, j), b = grid.at(i + 1, j), c = grid.at(i, j + 1), d = grid.at(i + 1, j + 1);
                if ((a && d && !b && !c) || (b && c && !a && !d)) {
                    grid.kept[(i + 1) + grid.nu * j] = 1;
                    changed = true;
                }
            }
    }
    return grid;
}

/// The closed boundary of the prisms over the kept cells, `layers` cells
/// thick: top and bottom quads and the walls along the region's boundary,
/// each quad two triangles. `layer_of[node]` is the node's layer (0 inner,
/// `layers` outer).
Mesh shell_surface(const FaceGeometry& g, const CellGrid& grid, int layers, std::vector<int>& layer_of)
{
    std::map<std::array<int, 3>, int> index;
    std::vector<Eigen::Vector3d> points;
    const auto node = [&](int i, int j, int k) {
        const auto [it, added] = index.emplace(std::array<int, 3>{i, j, k}, static_cast<int>(points.size()));
        if (added) {
            const Eigen::Vector2d xy = grid.xy(i, j);
            points.push_back(g.point(xy.x(), xy.y(), static_cast<double>(k) / layers));
            layer_of.push_back(k);
        }
        return it->second;
    };
    std::vector<std::array<int, 3>> triangles;
    const auto quad = [&](int a, int b, int c, int d) {
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, d});
    };
    for (int j = 0; j < grid.nv; ++j)
        for (int i = 0; i < grid.nu; ++i) {
            if (!grid.at(i, j))
                continue;
            quad(node(i, j, layers), node(i + 1, j, layers), node(i + 1, j + 1, layers), node(i, j + 1, layers));
            quad(node(i, j, 0), node(i, j + 1, 0), node(i + 1, j + 1, 0), node(i + 1, j, 0));
            // Walls where the neighbour across an edge is not kept: the edge's two grid nodes.
            const std::array<std::array<int, 5>, 4> edges = {{{i, j - 1, i, j, 0},
                                                              {i + 1, j, i + 1, j, 1},
                                                              {i, j + 1, i, j + 1, 0},
                                                              {i - 1, j, i, j, 1}}};
            for (const auto& e : edges) {
                if (grid.at(e[0], e[1]))
                    continue;
                const int pi = e[2], pj = e[3], qi = pi + (e[4] == 0 ? 1 : 0), qj = pj + (e[4] == 1 ? 1 : 0);
                for (int k = 0; k < layers; ++k)
                    quad(node(pi, pj, k), node(qi, qj, k), node(qi, qj, k + 1), node(pi, pj, k + 1));
            }
        }
    return triangle_surface(points, triangles);
}

/// TetGen on the surface with its volume bound calibrated so that the tet
/// count lands within kTetCountSlack of the target (one recalibration).
Mesh fill_with_tets(const Mesh& surface, double volume, int target)
{
    TetrahedralizeOptions options;
    options.preserve_surface = true;
    options.max_volume = volume / target;
    Mesh mesh = tetrahedralize_surface(surface, kSource, options);
    const double ratio = static_cast<double>(mesh.num_elements()) / target;
    if (std::abs(ratio - 1.0) > kTetCountSlack) {
        options.max_volume *= ratio;
        mesh = tetrahedralize_surface(surface, kSource, options);
    }
    return mesh;
}

/// A muscle as a band of the (x, y) plane around a segment, or the ring around the mouth.
struct MuscleBand {
    std::string name;
    Eigen::Vector2d from, to;
    double half_width;
};

double distance_to_segment(const Eigen::Vector2d& p, const MuscleBand& band)
{
    const Eigen::Vector2d d = band.to - band.from;
    const double t = std::clamp((p - band.from).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (p - band.from - t * d).norm();
}

std::vector<MuscleBand> muscle_bands(const FaceShape& s)
{
    const double my = s.mouth_y, mw = s.mouth_half_width;
    std::vector<MuscleBand> bands;
    for (const double side : {1.0, -1.0}) {
        const std::string label = side > 0 ? "_left" : "_right";
        bands.push_back({"zygomaticus_major" + label, {side * (mw + 0.034), my + 0.050}, {side * (mw + 0.004), my + 0.005}, 0.006});
        bands.push_back({"levator_labii" + label, {side * 0.022, my + 0.055}, {side * 0.012, my + 0.009}, 0.005});
        bands.push_back({"depressor_anguli_oris" + label, {side * (mw + 0.004), my - 0.007}, {side * (mw + 0.012), my - 0.040}, 0.006});
        bands.push_back({"frontalis" + label, {side * 0.025, my + 0.090}, {side * 0.025, my + 0.135}, 0.012});
    }
    bands.push_back({"mentalis", {0.0, my - 0.017}, {0.0, my - 0.045}, 0.008});
    return bands;
}

constexpr const char* kRingName = "orbicularis_oris";
constexpr double kRingWidth = 0.011;

/// Groups and fibers from each element's centroid: the ring first, then the bands.
void assign_muscles(const FaceGeometry& g, FaceMesh& face)
{
    const FaceShape& s = g.shape;
    const std::vector<MuscleBand> bands = muscle_bands(s);
    face.muscle_names = {kRingName};
    for (const MuscleBand& band : bands)
        face.muscle_names.push_back(band.name);
    Mesh& mesh = face.mesh;
    mesh.group_names = {"tissue"};
    mesh.group_names.insert(mesh.group_names.end(), face.muscle_names.begin(), face.muscle_names.end());
    face.muscle_elements.assign(face.muscle_names.size(), {});
    mesh.element_groups.assign(mesh.num_elements(), 0);
    mesh.element_fibers.resize(3, mesh.num_elements());
    const double A = s.mouth_half_width + kRingWidth, B = s.mouth_half_height + kRingWidth;
    for (int e = 0; e < mesh.num_elements(); ++e) {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k)
            centroid += 0.25 * mesh.nodes.col(mesh.elements(k, e));
        const double x = centroid.x(), y = centroid.y();
        const Eigen::Vector2d p(x, y);
        mesh.element_fibers.col(e) = g.tangent(x, y, Eigen::Vector2d::UnitX());
        if (g.thickness_fraction(centroid) < kMuscleDepth)
            continue;
        int muscle = -1;
        Eigen::Vector2d direction;
        const double yr = y - s.mouth_y;
        if (x * x / (A * A) + yr * yr / (B * B) <= 1.0 && !g.inside_mouth(x, y)) {
            muscle = 0;
            direction = Eigen::Vector2d(-yr / (B * B), x / (A * A));  // tangent of the ellipses about the mouth
        } else {
            for (std::size_t m = 0; m < bands.size() && muscle < 0; ++m)
                if (distance_to_segment(p, bands[m]) <= bands[m].half_width) {
                    muscle = static_cast<int>(m) + 1;
                    direction = bands[m].to - bands[m].from;
                }
        }
        if (muscle < 0 || direction.norm() == 0.0)
            continue;
        mesh.element_groups[e] = muscle + 1;
        mesh.element_fibers.col(e) = g.tangent(x, y, direction.normalized());
        face.muscle_elements[muscle].push_back(e);
    }
    for (std::size_t m = 0; m < face.muscle_names.size(); ++m)
        if (static_cast<int>(face.muscle_elements[m].size()) < kMinMuscleElements)
            throw InputError(std::string(kSource) + ": muscle '" + face.muscle_names[m] + "' has " +
                             std::to_string(face.muscle_elements[m].size()) +
                             " elements at this resolution; raise target_tets");
}

/// Cranium and jaw nodes among the inner surface's, landmarks among the outer's.
void select_nodes(const FaceGeometry& g, const std::vector<int>& layer_of, int layers, FaceMesh& face)
{
    const FaceShape& s = g.shape;
    const double jaw_top = g.jaw_top(), cranium_bottom = g.cranium_bottom(), jaw_half_width = g.jaw_half_width();
    std::vector<int> outer;
    for (int n = 0; n < static_cast<int>(layer_of.size()); ++n) {
        const Eigen::Vector3d X = face.mesh.nodes.col(n);
        if (layer_of[n] == layers) {
            outer.push_back(n);
        } else if (layer_of[n] == 0 && X.y() > cranium_bottom) {
            face.cranium_nodes.push_back(n);
        } else if (layer_of[n] == 0 && X.y() < jaw_top && std::abs(X.x()) < jaw_half_width) {
            face.jaw_nodes.push_back(n);
        } else {
            face.skull_contact_nodes.push_back(n);
        }
    }
    std::set<int> chosen;
    for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 9; ++i) {
            const double x = (-0.85 + 1.7 * i / 8.0) * s.rho * s.a, y = (-0.85 + 1.7 * j / 10.0) * s.rho * s.b;
            if (!g.inside_face(x / 0.95, y / 0.95) || g.inside_mouth(x, y, 0.004))
                continue;
            int best = -1;
            double best_distance = std::numeric_limits<double>::infinity();
            for (const int n : outer) {
                const double d = std::hypot(face.mesh.nodes(0, n) - x, face.mesh.nodes(1, n) - y);
                if (d < best_distance) {
                    best_distance = d;
                    best = n;
                }
            }
            if (best >= 0 && chosen.insert(best).second)
                face.landmarks.push_back(best);
        }
    if (static_cast<int>(face.landmarks.size()) < kMinLandmarks)
        throw InputError(std::string(kSource) + ": only " + std::to_string(face.landmarks.size()) +
                         " landmarks found; raise target_tets");
    if (face.cranium_nodes.empty() || face.jaw_nodes.empty())
        throw InputError(std::string(kSource) + ": no inner-surface node attached to the cranium or the jaw");
}

/// The shell's volume t·(area of the trimmed ellipse − mouth).
double shell_volume(const FaceShape& shape)
{
    return shape.thickness * M_PI *
           (shape.a * shape.b * shape.rho * shape.rho - shape.mouth_half_width * shape.mouth_half_height);
}

/// The tets' spacing: a regular tet of edge h has volume h³/(6√2), so
/// h = (6√2 V/N)^(1/3) for N tets.
double tet_spacing(const FaceShape& shape)
{
    return std::cbrt(6.0 * std::sqrt(2.0) * shell_volume(shape) / shape.target_tets);
}

/// Named node sets of the face's mesh, each sorted.
void name_node_sets(FaceMesh& face)
{
    std::vector<int> landmarks = face.landmarks;
    std::sort(landmarks.begin(), landmarks.end());
    face.mesh.node_sets = {{"cranium", face.cranium_nodes},
                           {"jaw", face.jaw_nodes},
                           {"skull_contact", face.skull_contact_nodes},
                           {"landmarks", landmarks}};
}

} // namespace

Mesh generate_face_skull(const FaceShape& shape)
{
    check_shape(shape);
    return face_skull(FaceGeometry{shape}, 0.5 * tet_spacing(shape));
}

FaceMesh generate_face(const FaceShape& shape)
{
    check_shape(shape);
    const FaceGeometry g{shape};
    const double volume = shell_volume(shape);
    const double spacing = tet_spacing(shape);
    const int layers = std::max(2, static_cast<int>(std::lround(shape.thickness / spacing)));
    std::vector<int> layer_of;
    const Mesh surface = shell_surface(g, cell_grid(g, spacing), layers, layer_of);

    FaceMesh face;
    face.mesh = fill_with_tets(surface, volume, shape.target_tets);
    // TetGen kept the surface (switch Y): its nodes come first, in order.
    for (int n = 0; n < surface.num_nodes(); ++n)
        if (face.mesh.nodes.col(n) != surface.nodes.col(n))
            throw InputError(std::string(kSource) + ": TetGen moved surface node " + std::to_string(n));
    assign_muscles(g, face);
    select_nodes(g, layer_of, layers, face);
    face.skull = face_skull(g, 0.5 * spacing, FaceBone::skull);
    face.maxilla = face_skull(g, 0.5 * spacing, FaceBone::maxilla);
    face.mandible = face_skull(g, 0.5 * spacing, FaceBone::mandible);
    name_node_sets(face);
    face.hinge_point = Eigen::Vector3d(0.0, shape.mouth_y + 0.04, -0.02);
    return face;
}

} // namespace sinew
