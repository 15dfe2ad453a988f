#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/energies/models/model_parameters.hpp"
#include "sinew/mesh/mesh.hpp"

#include <memory>
#include <string>
#include <variant>

namespace sinew {

/// A constitutive model of any shape of F: 3×3 (tets), 2×2 (triangles in 2D)
/// or 3×2 (triangles in 3D). The elastic potential checks that a group's
/// model has the shape of the mesh's elements.
using ElementModel = std::variant<std::shared_ptr<const Model3d>, std::shared_ptr<const Model2d>,
                                  std::shared_ptr<const MembraneModel>>;

/// "3x3", "2x2" or "3x2": the shape of F the model takes.
std::string shape_of(const ElementModel& model);
/// The same for the elements of a kind.
std::string shape_of(ElementKind kind);
/// The model's name, or "null" when it holds no model.
std::string name_of(const ElementModel& model);

/// Model `name` from the catalog, built for the F shape of `kind`
/// (make_model<Rows, Cols>): InputError for an unknown name, an invalid
/// parameter, or a model that does not take that shape.
ElementModel make_element_model(ElementKind kind, const std::string& name, const ParameterValues& parameters);
/// The same from parameters as text (a scene file, the command line): the
/// catalog parses and checks them.
ElementModel parse_element_model(ElementKind kind, const std::string& name, const ParameterText& parameters);

} // namespace sinew
