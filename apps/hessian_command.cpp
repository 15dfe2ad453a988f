#include "commands.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/problems/builtin_problems.hpp"
#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/output_file.hpp"
#include "sinew/solvers/newton/pattern_matrix.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

namespace sinew::cli {
namespace {

/// The lower triangle of A in Matrix Market's "coordinate real symmetric"
/// format (1-based indices, 17 significant digits).
std::string matrix_market(const SparseMatrix& A)
{
    std::ostringstream out;
    out << "%%MatrixMarket matrix coordinate real symmetric\n"
        << "% written by sinew hessian: the Hessian a Newton iteration factorizes\n"
        << A.rows() << " " << A.cols() << " " << A.nonZeros() << "\n";
    char line[96];
    for (int col = 0; col < A.outerSize(); ++col)
        for (SparseMatrix::InnerIterator entry(A, col); entry; ++entry) {
            std::snprintf(line, sizeof line, "%d %d %.17g\n", static_cast<int>(entry.row()) + 1, col + 1,
                          entry.value());
            out << line;
        }
    return out.str();
}

} // namespace

void add_hessian_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand(
        "hessian", "write the Hessian of a problem at its starting point, as the first Newton iteration factorizes "
                   "it (PSD-projected where the problem offers that; lower triangle, Matrix Market), for "
                   "factorization benchmarks such as bench/cholmod_factorize");
    struct Flags {
        std::string problem, out;
        bool exact = false;
    };
    auto flags = std::make_shared<Flags>();
    command->add_option("problem", flags->problem, "a built-in problem or a scene file *.json")->required();
    command->add_option("--out", flags->out, "the Matrix Market file to write")->required();
    command->add_flag("--exact", flags->exact, "the exact Hessian, without the PSD projection");
    command->callback([flags, &exit_code] {
        check_writable(flags->out);
        std::unique_ptr<Nlp> nlp = std::filesystem::path(flags->problem).extension() == ".json"
                                       ? std::move(read_scene_file(flags->problem).problem)
                                       : find_builtin_problem(flags->problem).make();
        if (!nlp)
            throw InputError(flags->problem + ": an mpm scene has no single NLP to write (its steps pose one each)");
        const Projection projection =
            !flags->exact && nlp->supports(Projection::clamp) ? Projection::clamp : Projection::none;
        Eigen::VectorXd values(nlp->hessian_pattern().nonzeros());
        nlp->hessian(nlp->starting_point(), 1.0, Eigen::VectorXd::Zero(nlp->num_constraints()), projection, values);
        PatternMatrix H(nlp->hessian_pattern(), nlp->num_variables());
        H.fill(values);
        write_text_file(flags->out, matrix_market(H.matrix()));
        std::cerr << "sinew: wrote " << flags->out << ": " << H.matrix().rows() << " × " << H.matrix().cols()
                  << ", " << H.matrix().nonZeros() << " stored entries (lower triangle), "
                  << (projection == Projection::clamp ? "PSD-projected" : "exact") << "\n";
        exit_code = 0;
    });
}

} // namespace sinew::cli
