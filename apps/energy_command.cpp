// sinew energy: evaluate one constitutive model at one deformation gradient.
#include "cli_options.hpp"
#include "commands.hpp"
#include "sinew/runs/result_json.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/core/parse_number.hpp"
#include "sinew/energies/models/model_catalog.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>

namespace sinew::cli {
namespace {

struct EnergyFlags {
    bool list = false;
    std::string model;
    std::vector<std::string> parameters;  ///< "key=value" texts
    std::string deformation;              ///< F row by row
    std::vector<std::string> fiber;
    std::string activation = "0";
    std::string damage = "0";
    bool projected = false;
};

std::vector<double> parse_numbers(const std::string& text, const std::string& what)
{
    std::istringstream words(text);
    std::vector<double> numbers;
    std::string word;
    while (words >> word)
        numbers.push_back(parse_finite_double(word, what + " entry " + std::to_string(numbers.size() + 1)));
    return numbers;
}

void print_catalog()
{
    for (const ModelEntry& entry : model_catalog()) {
        std::string shapes;
        for (const auto& s : entry.shapes())
            shapes += (shapes.empty() ? "" : ", ") + s;
        std::cout << entry.name << "  (F " << shapes << ")\n  " << entry.description << "\n";
        for (const ParameterSpec& p : entry.parameters) {
            std::cout << "    " << p.name << " = ";
            if (p.choices.empty())
                std::cout << p.default_value << " " << p.unit;
            else {
                std::cout << p.choices[static_cast<size_t>(p.default_value)] << " (one of";
                for (const auto& c : p.choices)
                    std::cout << " " << c;
                std::cout << ")";
            }
            std::cout << "  " << p.description << "\n";
        }
    }
}

/// ψ, P and ∂P/∂F at F as {"psi", "P"[i][j], "dPdF"[i][j][k][l] = ∂P_ij/∂F_kl}.
template <int Rows, int Cols>
nlohmann::json evaluate(const EnergyFlags& flags, const ParameterText& parameters,
                        const std::vector<double>& entries)
{
    const auto model = make_model<Rows, Cols>(flags.model, parameters);
    using Model = ConstitutiveModel<Rows, Cols>;
    typename Model::Deformation F;
    for (int i = 0; i < Rows; ++i)
        for (int j = 0; j < Cols; ++j)
            F(i, j) = entries[static_cast<size_t>(i * Cols + j)];

    typename Model::Point point;
    if (!flags.fiber.empty()) {
        if (flags.fiber.size() != static_cast<size_t>(Cols))
            throw InputError("--fiber takes " + std::to_string(Cols) + " numbers for a " + std::to_string(Rows) +
                             "x" + std::to_string(Cols) + " F, got " + std::to_string(flags.fiber.size()));
        for (int i = 0; i < Cols; ++i)
            point.fiber[i] = parse_finite_double(flags.fiber[static_cast<size_t>(i)],
                                                 "--fiber entry " + std::to_string(i + 1));
        if (point.fiber.norm() == 0.0)
            throw InputError("--fiber must not be the zero vector");
        point.fiber.normalize();
    }
    point.activation = parse_finite_double(flags.activation, "--activation");
    point.damage = parse_finite_double(flags.damage, "--damage");
    if (point.activation < 0.0 || point.activation > 1.0)
        throw InputError("--activation must lie in [0, 1], got " + flags.activation);
    if (point.damage < 0.0 || point.damage > 1.0)
        throw InputError("--damage must lie in [0, 1], got " + flags.damage);

    typename Model::Stress P;
    typename Model::Stiffness dPdF;
    const double psi =
        model->evaluate(F, point, &P, &dPdF, flags.projected ? Projection::clamp : Projection::none);

    nlohmann::json stress = nlohmann::json::array();
    nlohmann::json stiffness = nlohmann::json::array();
    for (int i = 0; i < Rows; ++i) {
        nlohmann::json stress_row = nlohmann::json::array();
        nlohmann::json stiffness_i = nlohmann::json::array();
        for (int j = 0; j < Cols; ++j) {
            stress_row.push_back(number(P(i, j)));
            nlohmann::json stiffness_ij = nlohmann::json::array();
            for (int k = 0; k < Rows; ++k) {
                nlohmann::json stiffness_ijk = nlohmann::json::array();
                for (int l = 0; l < Cols; ++l)
                    stiffness_ijk.push_back(number(dPdF(i + Rows * j, k + Rows * l)));  // column-major vec(F)
                stiffness_ij.push_back(stiffness_ijk);
            }
            stiffness_i.push_back(stiffness_ij);
        }
        stress.push_back(stress_row);
        stiffness.push_back(stiffness_i);
    }
    return {{"psi", number(psi)}, {"P", stress}, {"dPdF", stiffness}};
}

} // namespace

void add_energy_command(CLI::App& app, int& exit_code)
{
    CLI::App* command = app.add_subcommand(
        "energy", "evaluate a constitutive model at one F: prints {\"psi\", \"P\", \"dPdF\"} as JSON with "
                  "dPdF[i][j][k][l] = dP_ij/dF_kl");
    auto flags = std::make_shared<EnergyFlags>();
    command->add_flag("--list", flags->list, "list every model with its parameters, defaults and units");
    command->add_option("--model", flags->model, "model name (see --list)");
    command->add_option("--param", flags->parameters, "model parameter key=value (repeatable)");
    command->add_option("--F", flags->deformation,
                        "F row by row: 9 numbers for 3x3 models, 4 for 2D, 6 for the 3x2 membrane");
    command->add_option("--fiber", flags->fiber, "fiber direction in material space (3 numbers; 2 for 2D and 3x2)")
        ->expected(2, 3);
    command->add_option("--activation", flags->activation, "muscle activation in [0, 1]")->capture_default_str();
    command->add_option("--damage", flags->damage, "damage in [0, 1]")->capture_default_str();
    command->add_flag("--projected", flags->projected, "PSD-projected dPdF");

    command->callback([flags, &exit_code] {
        if (flags->list) {
            print_catalog();
            exit_code = 0;
            return;
        }
        if (flags->model.empty())
            throw InputError("energy needs --model (or --list)");
        if (flags->deformation.empty())
            throw InputError("energy needs --F with the entries of F row by row");
        const ModelEntry& entry = find_model(flags->model);
        ParameterText parameters;
        for (const std::string& text : flags->parameters) {
            const auto [key, value] = split_key_value(text, "--param");
            parameters[key] = value;
        }
        const std::vector<double> entries = parse_numbers(flags->deformation, "--F");
        const auto shapes = entry.shapes();
        auto takes = [&](const char* shape) { return std::find(shapes.begin(), shapes.end(), shape) != shapes.end(); };
        nlohmann::json out;
        if (entries.size() == 9 && takes("3x3"))
            out = evaluate<3, 3>(*flags, parameters, entries);
        else if (entries.size() == 4 && takes("2x2"))
            out = evaluate<2, 2>(*flags, parameters, entries);
        else if (entries.size() == 6 && takes("3x2"))
            out = evaluate<3, 2>(*flags, parameters, entries);
        else {
            std::string expected;
            for (const auto& s : shapes)
                expected += std::string(expected.empty() ? "" : " or ") +
                            (s == "3x3" ? "9" : s == "2x2" ? "4" : "6") + " (" + s + ")";
            throw InputError("--F has " + std::to_string(entries.size()) + " numbers; model '" + flags->model +
                             "' takes " + expected);
        }
        std::cout << out.dump() << "\n";
        exit_code = 0;
    });
}

} // namespace sinew::cli
