#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/model_parameters.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sinew {

/// A constitutive model by name: its parameters and a maker for each shape
/// of F it takes (3×3 solids, 2×2 plane, 3×2 membranes); an empty maker
/// means the model does not take that shape.
struct ModelEntry {
    std::string name;
    std::string description;
    std::vector<ParameterSpec> parameters;
    std::function<std::unique_ptr<Model3d>(const ParameterValues&)> make_3x3;
    std::function<std::unique_ptr<Model2d>(const ParameterValues&)> make_2x2;
    std::function<std::unique_ptr<MembraneModel>(const ParameterValues&)> make_3x2;

    /// "3x3", "2x2", "3x2" for the shapes it takes.
    std::vector<std::string> shapes() const;
};

/// Every model sinew ships, in a fixed order.
const std::vector<ModelEntry>& model_catalog();

/// The model called `name`; InputError listing the valid names otherwise.
const ModelEntry& find_model(const std::string& name);

/// Builds model `name` for F of Rows × Cols from parameters given as text
/// (validated: unknown parameter, malformed or non-finite number, out of
/// range). InputError naming the shapes it takes when it takes no Rows × Cols F.
template <int Rows, int Cols>
std::unique_ptr<ConstitutiveModel<Rows, Cols>> make_model(const std::string& name, const ParameterText& parameters);

/// Same from numbers, for code that builds models directly.
template <int Rows, int Cols>
std::unique_ptr<ConstitutiveModel<Rows, Cols>> make_model(const std::string& name,
                                                          const ParameterValues& parameters);

} // namespace sinew
