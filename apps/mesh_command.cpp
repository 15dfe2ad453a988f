#include "commands.hpp"

#include "sinew/mesh/face_mesh.hpp"
#include "sinew/mesh/vtu_writer.hpp"
#include "sinew/runs/output_file.hpp"

#include <iostream>
#include <memory>

namespace sinew::cli {
namespace {

/// Groups and fibers per cell; per point, the attachment (0 free, 1 cranium,
/// 2 jaw) and the landmark number (1-based, 0 for none).
void write_face(const std::string& path, const FaceMesh& face)
{
    const Mesh& mesh = face.mesh;
    Eigen::MatrixXd group(1, mesh.num_elements());
    for (int e = 0; e < mesh.num_elements(); ++e)
        group(0, e) = mesh.element_groups[e];
    Eigen::MatrixXd attachment = Eigen::MatrixXd::Zero(1, mesh.num_nodes());
    Eigen::MatrixXd landmark = Eigen::MatrixXd::Zero(1, mesh.num_nodes());
    for (const int n : face.cranium_nodes)
        attachment(0, n) = 1;
    for (const int n : face.jaw_nodes)
        attachment(0, n) = 2;
    for (std::size_t l = 0; l < face.landmarks.size(); ++l)
        landmark(0, face.landmarks[l]) = static_cast<double>(l + 1);
    write_vtu(path, mesh, mesh.nodes, {{"attachment", attachment}, {"landmark", landmark}},
              {{"group", group}, {"fiber", mesh.element_fibers}});
}

} // namespace

void add_mesh_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand("mesh", "generate a mesh");
    command->require_subcommand(1);
    CLI::App* face = command->add_subcommand(
        "face", "a face for the muscle-driven rig: a tissue shell with a mouth, ten muscles with fibers, cranium and "
                "jaw attachments and landmarks (docs/inverse.md), as VTU with groups, fibers, attachments, landmarks");
    struct Flags {
        int tets = 20000;
        std::string out = "face.vtu";
    };
    auto flags = std::make_shared<Flags>();
    face->add_option("--tets", flags->tets, "the number of tetrahedra aimed at (within 25 %)")->capture_default_str();
    face->add_option("--out", flags->out, "the VTU file to write")->capture_default_str();
    face->callback([flags, &exit_code] {
        check_writable(flags->out);
        FaceShape shape;
        shape.target_tets = flags->tets;
        const FaceMesh generated = generate_face(shape);
        write_face(flags->out, generated);
        std::cerr << "sinew: wrote " << flags->out << ": " << generated.mesh.num_elements() << " tets, "
                  << generated.mesh.num_nodes() << " nodes, " << generated.muscle_names.size() << " muscles, "
                  << generated.landmarks.size() << " landmarks, " << generated.cranium_nodes.size()
                  << " cranium and " << generated.jaw_nodes.size() << " jaw nodes\n";
        exit_code = 0;
    });
}

} // namespace sinew::cli
