#include "sinew/mesh/tetrahedralize_surface.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/mesh/element_orientation.hpp"
#include "sinew/mesh/mesh_validation.hpp"
#include "sinew/mesh/obj_reader.hpp"
#include "sinew/mesh/remove_unused_nodes.hpp"
#include "sinew/mesh/tetgen_run.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace sinew {
namespace {

void check_options(const TetrahedralizeOptions& options, const std::string& source)
{
    std::ostringstream message;
    if (!(std::isfinite(options.max_volume) && options.max_volume >= 0.0))
        message << "max_volume = " << format_number(options.max_volume) << " must be 0 (no bound) or positive";
    else if (!(options.max_radius_edge_ratio == 0.0 ||
               (std::isfinite(options.max_radius_edge_ratio) && options.max_radius_edge_ratio >= 1.0)))
        message << "max_radius_edge_ratio = " << format_number(options.max_radius_edge_ratio)
                << " must be 0 (off) or at least 1";
    else
        return;
    throw InputError(source + ": tetrahedralize: " + message.str());
}

/// Every edge of a closed surface lies in exactly two triangles.
void check_closed(const Mesh& surface, const std::string& source)
{
    std::map<std::pair<int, int>, std::vector<int>> triangles_of_edge;
    for (int e = 0; e < surface.num_elements(); ++e)
        for (int k = 0; k < 3; ++k) {
            const int a = surface.elements(k, e);
            const int b = surface.elements((k + 1) % 3, e);
            triangles_of_edge[{std::min(a, b), std::max(a, b)}].push_back(e);
        }
    for (const auto& [edge, triangles] : triangles_of_edge)
        if (triangles.size() != 2)
            throw InputError(source + ": element " + std::to_string(triangles.front()) + ": its edge between nodes " +
                             std::to_string(edge.first) + " and " + std::to_string(edge.second) + " is in " +
                             std::to_string(triangles.size()) +
                             " triangle(s); a closed surface has every edge in exactly 2");
}

std::array<int, 3> sorted_corners(const Eigen::Ref<const Eigen::VectorXi>& corners)
{
    std::array<int, 3> sorted{corners[0], corners[1], corners[2]};
    std::sort(sorted.begin(), sorted.end());
    return sorted;
}

/// TetGen's intersection detection (switch d) lists the input triangles that
/// cross others; name the first as an element of the surface.
void check_no_self_intersection(const Mesh& surface, const std::string& source)
{
    const Eigen::MatrixXi crossing = run_tetgen(surface, "pdQ", source).faces;
    if (crossing.cols() == 0)
        return;
    std::map<std::array<int, 3>, int> element_of;
    for (int e = 0; e < surface.num_elements(); ++e)
        element_of.emplace(sorted_corners(surface.elements.col(e)), e);
    const auto first = element_of.find(sorted_corners(crossing.col(0)));
    const std::string example =
        first == element_of.end() ? "" : " (element " + std::to_string(first->second) + " is one)";
    throw InputError(source + ": the surface intersects itself: " + std::to_string(crossing.cols()) +
                     " triangles cross other triangles" + example);
}

/// The volume a closed, consistently oriented surface encloses (divergence
/// theorem): |Σ x0·(x1 × x2)| / 6 over its triangles.
double enclosed_volume(const Mesh& surface)
{
    double sum = 0.0;
    for (int e = 0; e < surface.num_elements(); ++e) {
        const Eigen::Vector3d x0 = surface.nodes.col(surface.elements(0, e));
        const Eigen::Vector3d x1 = surface.nodes.col(surface.elements(1, e));
        const Eigen::Vector3d x2 = surface.nodes.col(surface.elements(2, e));
        sum += x0.dot(x1.cross(x2));
    }
    return std::abs(sum) / 6.0;
}

/// No tet is larger than max_volume, so TetGen makes at least V / max_volume
/// of them: refuse before starting when that exceeds kMaxGeneratedElements.
void check_estimated_size(const Mesh& surface, const TetrahedralizeOptions& options, const std::string& source)
{
    if (options.max_volume <= 0.0)
        return;
    const double at_least = enclosed_volume(surface) / options.max_volume;
    if (at_least > kMaxGeneratedElements)
        throw InputError(source + ": tetrahedralize: max_volume = " + format_number(options.max_volume) +
                         " asks for at least " + format_number(std::ceil(at_least)) +
                         " tetrahedra (enclosed volume " + format_number(enclosed_volume(surface)) +
                         "); the limit is " + format_number(kMaxGeneratedElements));
}

/// TetGen may add at most this many points (switch S): about six tets per
/// point, so a run that reaches it would exceed kMaxGeneratedElements.
constexpr int kMaxAddedPoints = static_cast<int>(kMaxGeneratedElements / 6);

/// TetGen's switches: p (mesh the surface as a piecewise linear complex),
/// Q (quiet), S<points>, q<ratio>, a<volume>, Y (preserve the surface).
std::string tetgen_switches(const TetrahedralizeOptions& options)
{
    std::ostringstream switches;
    switches.precision(std::numeric_limits<double>::max_digits10);
    switches << "pQS" << kMaxAddedPoints;
    if (options.max_radius_edge_ratio > 0.0)
        switches << "q" << options.max_radius_edge_ratio;
    if (options.max_volume > 0.0)
        switches << "a" << options.max_volume;
    if (options.preserve_surface)
        switches << "Y";
    return switches.str();
}

} // namespace

Mesh tetrahedralize_surface(const Mesh& surface, const std::string& source, const TetrahedralizeOptions& options)
{
    check_options(options, source);
    if (surface.kind != ElementKind::triangle_3d)
        throw InputError(source + ": tetrahedralize needs a triangle surface in 3D, got a " +
                         to_string(surface.kind) + " mesh");
    validate_mesh(surface, source);
    check_closed(surface, source);
    check_no_self_intersection(surface, source);
    check_estimated_size(surface, options, source);

    TetgenOutput output = run_tetgen(surface, tetgen_switches(options), source);
    if (output.tetrahedra.cols() == 0)
        throw InputError(source + ": TetGen produced no tetrahedra (does the surface enclose a volume?)");
    if (output.points.cols() - surface.num_nodes() >= kMaxAddedPoints)
        throw InputError(source + ": tetrahedralize: TetGen reached its limit of " + std::to_string(kMaxAddedPoints) +
                         " added points before meeting the quality and volume bounds; relax max_volume or "
                         "max_radius_edge_ratio");
    Mesh mesh;
    mesh.kind = ElementKind::tetrahedron;
    mesh.nodes = std::move(output.points);
    mesh.elements = std::move(output.tetrahedra);
    mesh.group_names = {kDefaultGroupName};
    mesh.element_groups.assign(mesh.num_elements(), 0);
    remove_unused_nodes(mesh);
    orient_elements_positively(mesh);
    validate_mesh(mesh, source + " (tetrahedralized by TetGen)");
    return mesh;
}

Mesh tetrahedralize_obj(const std::string& obj_path, const TetrahedralizeOptions& options)
{
    return tetrahedralize_surface(read_obj(obj_path), obj_path, options);
}

} // namespace sinew
