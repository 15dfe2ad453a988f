#include "sinew/energies/potentials/elastic_potential.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/assembly_schedule.hpp"
#include "sinew/energies/potentials/element_rest_shape.hpp"
#include "sinew/energies/potentials/hessian_pattern.hpp"
#include "sinew/energies/potentials/simplex_kinematics.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

namespace sinew {
namespace detail {

/// The elastic potential's work for one shape of F, behind one virtual call
/// per evaluation (never per element).
class ElasticElements {
public:
    using VectorRef = Potential::VectorRef;
    using ConstVectorRef = Potential::ConstVectorRef;

    virtual ~ElasticElements() = default;
    virtual int dimension() const = 0;
    virtual int num_nodes() const = 0;
    virtual int num_elements() const = 0;
    virtual int num_colors() const = 0;
    virtual int num_blocks() const = 0;
    virtual const Stencils& stencils() const = 0;
    virtual double value(ConstVectorRef x) = 0;
    virtual void add_gradient(ConstVectorRef x, VectorRef gradient) const = 0;
    virtual void add_hessian(ConstVectorRef x, Projection projection, const StencilSlots& slots,
                             VectorRef values) const = 0;
    virtual void add_activation_gradient(ConstVectorRef x, const std::vector<int>& elements,
                                         VectorRef gradient) const = 0;
    virtual Eigen::VectorXd stress_norms(ConstVectorRef x) const = 0;
    virtual void set_fiber(int element, const Eigen::VectorXd& fiber) = 0;
    virtual Eigen::VectorXd fiber(int element) const = 0;
    virtual void set_activation(int element, double activation) = 0;
    virtual double activation(int element) const = 0;
    virtual void set_damage(int element, double damage) = 0;
    virtual double damage(int element) const = 0;
};

} // namespace detail

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// At most this many elements go to one ConstitutiveModel::evaluate_batch call.
constexpr int kElementBatch = 16;

std::string element_label(int element) { return "elastic potential: element " + std::to_string(element); }

/// Runs `work` inside a parallel loop, keeping the first exception it throws
/// (a model refusing its input) in `error` for the caller to rethrow after the
/// loop: an exception must not leave an OpenMP region.
template <typename Work>
void guarded(std::exception_ptr& error, const Work& work)
{
    try {
        work();
    } catch (...) {
#pragma omp critical(sinew_elastic_potential_error)
        if (!error)
            error = std::current_exception();
    }
}

template <int Rows, int Cols>
class TypedElasticElements final : public detail::ElasticElements {
public:
    using Kinematics = SimplexKinematics<Rows, Cols>;
    using Model = ConstitutiveModel<Rows, Cols>;
    using Point = MaterialPoint<Cols>;
    using RestInverse = typename Kinematics::RestInverse;
    using Membrane = Eigen::Matrix<double, 3, 2>;
    static constexpr bool kMembrane = Rows == 3 && Cols == 2;

    TypedElasticElements(const Mesh& mesh, std::vector<std::shared_ptr<const Model>> group_models)
        : num_nodes_(mesh.num_nodes()),
          elements_(mesh.elements),
          models_(std::move(group_models)),
          groups_(mesh.element_groups),
          schedule_(schedule_assembly(mesh.nodes, mesh.elements))
    {
        const int count = mesh.num_elements();
        rest_inverse_.resize(count);
        measure_.resize(count);
        points_.resize(count);
        energies_.assign(count, 0.0);
        if constexpr (kMembrane)
            frames_.resize(count);
        for (int e = 0; e < count; ++e) {
            measure_[e] = rest_measure(mesh, e);
            rest_inverse_[e] = rest_edge_matrix<Cols>(mesh, e).inverse();
            if constexpr (kMembrane)
                frames_[e] = membrane_rest_frame(mesh.nodes.col(mesh.elements(0, e)),
                                                 mesh.nodes.col(mesh.elements(1, e)),
                                                 mesh.nodes.col(mesh.elements(2, e)));
        }
        if (mesh.element_fibers.size() > 0) {
            const bool spatial = kMembrane && mesh.element_fibers.rows() == 3;
            if ((mesh.element_fibers.rows() != Cols && !spatial) || mesh.element_fibers.cols() != count)
                throw InputError("elastic potential: mesh fibers are " + std::to_string(mesh.element_fibers.rows()) +
                                 "x" + std::to_string(mesh.element_fibers.cols()) + ", expected " +
                                 std::to_string(Cols) + "x" + std::to_string(count));
            for (int e = 0; e < count; ++e)
                set_fiber(e, mesh.element_fibers.col(e));
        }
    }

    int dimension() const override { return Rows; }
    int num_nodes() const override { return num_nodes_; }
    int num_elements() const override { return static_cast<int>(elements_.cols()); }
    int num_colors() const override { return schedule_.num_colors(); }
    int num_blocks() const override { return schedule_.num_blocks(); }
    const Stencils& stencils() const override { return elements_; }

    double value(ConstVectorRef x) override
    {
        const int count = num_elements();
        const int chunks = (count + kElementBatch - 1) / kElementBatch;
        std::exception_ptr error;
        // ψ alone, in runs of consecutive elements of one model (evaluate_batch
        // with no P or ∂P/∂F: several elements side by side in SIMD lanes).
#pragma omp parallel for schedule(static)
        for (int chunk = 0; chunk < chunks; ++chunk)
            guarded(error, [&] {
                Batch batch;
                double psi[kElementBatch];
                const int end = std::min(count, (chunk + 1) * kElementBatch);
                for (int first = chunk * kElementBatch; first < end;) {
                    int run = 0;
                    while (first + run < end && groups_[first + run] == groups_[first]) {
                        batch.F[run] = deformation_gradient(x, first + run);
                        batch.points[run] = points_[first + run];
                        ++run;
                    }
                    model(first).evaluate_batch(run, batch.F, batch.points, psi, nullptr, nullptr, Projection::none);
                    for (int k = 0; k < run; ++k)
                        energies_[first + k] = measure_[first + k] * psi[k];
                    first += run;
                }
            });
        if (error)
            std::rethrow_exception(error);
        // A fixed order of summation, whatever the threads did.
        double sum = 0.0;
        for (int e = 0; e < count; ++e) {
            if (!(energies_[e] < kInfinity))  // +∞ or NaN
                return kInfinity;
            sum += energies_[e];
        }
        return sum < kInfinity ? sum : kInfinity;
    }

    void add_gradient(ConstVectorRef x, VectorRef gradient) const override
    {
        double* out = gradient.data();
        for_each_batch(x, [&](const int* elements, int count, const Batch& batch) {
            typename Model::Stress P[kElementBatch];
            double psi[kElementBatch];
            model(elements[0]).evaluate_batch(count, batch.F, batch.points, psi, P, nullptr, Projection::none);
            for (int k = 0; k < count; ++k) {
                const int e = elements[k];
                const typename Kinematics::NodalVectors g = Kinematics::gradient(P[k], rest_inverse_[e], measure_[e]);
                for (int a = 0; a < Kinematics::kNodes; ++a)
                    for (int i = 0; i < Rows; ++i)
                        out[elements_(a, e) * Rows + i] += g(i, a);
            }
        });
    }

    void add_hessian(ConstVectorRef x, Projection projection, const StencilSlots& slots,
                     VectorRef values) const override
    {
        double* out = values.data();
        for_each_batch(x, [&](const int* elements, int count, const Batch& batch) {
            typename Model::Stiffness dPdF[kElementBatch];
            double psi[kElementBatch];
            model(elements[0]).evaluate_batch(count, batch.F, batch.points, psi, nullptr, dPdF, projection);
            for (int k = 0; k < count; ++k) {
                const int e = elements[k];
                typename Kinematics::LocalHessian H;
                Kinematics::lower_hessian(dPdF[k], rest_inverse_[e], measure_[e], H);
                add_lower_triangle(H, &slots(0, e), out);
            }
        });
    }

    void add_activation_gradient(ConstVectorRef x, const std::vector<int>& elements,
                                 VectorRef gradient) const override
    {
        double* out = gradient.data();
        for (const int e : elements) {
            typename Model::Stress dP_dalpha;
            model(e).activation_derivative(deformation_gradient(x, e), points_[e], &dP_dalpha);
            const typename Kinematics::NodalVectors g = Kinematics::gradient(dP_dalpha, rest_inverse_[e], measure_[e]);
            for (int a = 0; a < Kinematics::kNodes; ++a)
                for (int i = 0; i < Rows; ++i)
                    out[elements_(a, e) * Rows + i] += g(i, a);
        }
    }

    Eigen::VectorXd stress_norms(ConstVectorRef x) const override
    {
        const int count = num_elements();
        Eigen::VectorXd norms(count);
        std::exception_ptr error;
#pragma omp parallel for schedule(static)
        for (int e = 0; e < count; ++e)
            guarded(error, [&] {
                typename Model::Stress P;
                model(e).evaluate(deformation_gradient(x, e), points_[e], &P, nullptr, Projection::none);
                norms[e] = P.norm();
            });
        if (error)
            std::rethrow_exception(error);
        return norms;
    }

    void set_fiber(int element, const Eigen::VectorXd& fiber) override
    {
        const bool spatial = kMembrane && fiber.size() == 3;
        if (fiber.size() != Cols && !spatial)
            throw InputError(element_label(element) + ": fiber has " + std::to_string(fiber.size()) +
                             " components, expected " + std::to_string(Cols) + (kMembrane ? " or 3" : ""));
        if (!fiber.allFinite())
            throw InputError(element_label(element) + ": fiber is not finite");
        const Eigen::Matrix<double, Cols, 1> a = material_direction(element, fiber);
        const double length = a.norm();
        if (!(length > 1e-8 * fiber.norm()))
            throw InputError(element_label(element) + (kMembrane ? ": fiber is zero or normal to the rest plane"
                                                                  : ": fiber is zero"));
        points_[element].fiber = a / length;
    }

    Eigen::VectorXd fiber(int element) const override { return points_[element].fiber; }
    void set_activation(int element, double activation) override { points_[element].activation = activation; }
    double activation(int element) const override { return points_[element].activation; }
    void set_damage(int element, double damage) override { points_[element].damage = damage; }
    double damage(int element) const override { return points_[element].damage; }

private:
    const Model& model(int element) const { return *models_[groups_[element]]; }

    /// F and the material point of the elements of one batch.
    struct Batch {
        typename Model::Deformation F[kElementBatch];
        Point points[kElementBatch];
    };

    /// Runs `add(elements, count, batch)` over the assembly schedule in
    /// batches: runs of at most kElementBatch consecutive elements of one block
    /// that share a model, with their F and material points. Colors in order,
    /// the blocks of a color in parallel, each block's elements in order
    /// (assembly_schedule.hpp: deterministic for any thread count).
    template <typename AddBatch>
    void for_each_batch(ConstVectorRef x, const AddBatch& add) const
    {
        std::exception_ptr error;
        for (int c = 0; c < schedule_.num_colors() && !error; ++c) {
            const int first = schedule_.color_starts[c];
            const int last = schedule_.color_starts[c + 1];
#pragma omp parallel for schedule(dynamic, 1)
            for (int b = first; b < last; ++b)
                guarded(error, [&] {
                    Batch batch;
                    const int end = schedule_.block_starts[b + 1];
                    for (int k = schedule_.block_starts[b]; k < end;) {
                        const int* elements = &schedule_.elements[k];
                        int count = 0;
                        while (count < kElementBatch && k + count < end &&
                               groups_[elements[count]] == groups_[elements[0]]) {
                            batch.F[count] = deformation_gradient(x, elements[count]);
                            batch.points[count] = points_[elements[count]];
                            ++count;
                        }
                        add(elements, count, batch);
                        k += count;
                    }
                });
        }
        if (error)
            std::rethrow_exception(error);
    }

    /// A fiber of Cols components as it is; for membranes a direction in
    /// space written in the element's rest frame (its in-plane part).
    Eigen::Matrix<double, Cols, 1> material_direction(int element, const Eigen::VectorXd& fiber) const
    {
        if constexpr (kMembrane)
            if (fiber.size() == 3)
                return frames_[element].transpose() * Eigen::Vector3d(fiber);
        return fiber;
    }

    typename Kinematics::Deformation deformation_gradient(ConstVectorRef x, int element) const
    {
        typename Kinematics::Positions xe;
        for (int a = 0; a < Kinematics::kNodes; ++a)
            xe.col(a) = x.segment<Rows>(elements_(a, element) * Rows);
        return Kinematics::deformation_gradient(xe, rest_inverse_[element]);
    }

    int num_nodes_;
    Stencils elements_;
    std::vector<std::shared_ptr<const Model>> models_;
    std::vector<int> groups_;
    AssemblySchedule schedule_;
    std::vector<RestInverse> rest_inverse_;  ///< Dm⁻¹ per element
    std::vector<double> measure_;            ///< W_e per element
    std::vector<Point> points_;
    std::vector<Membrane> frames_;           ///< rest frames (triangles in 3D only)
    std::vector<double> energies_;           ///< W_e ψ_e of the last value() call
};

/// The models of every group as the shape the kind needs; InputError naming
/// the group whose model is null or of another shape.
template <int Rows, int Cols>
std::vector<std::shared_ptr<const ConstitutiveModel<Rows, Cols>>>
typed_models(const Mesh& mesh, const std::vector<ElementModel>& group_models)
{
    using Pointer = std::shared_ptr<const ConstitutiveModel<Rows, Cols>>;
    std::vector<Pointer> typed;
    for (std::size_t g = 0; g < group_models.size(); ++g) {
        const std::string group = "elastic potential: group " + std::to_string(g) +
                                  (g < mesh.group_names.size() ? " ('" + mesh.group_names[g] + "')" : "");
        const Pointer* model = std::get_if<Pointer>(&group_models[g]);
        if (!model)
            throw InputError(group + " has model '" + name_of(group_models[g]) + "' of F shape " +
                             shape_of(group_models[g]) + ", but " + to_string(mesh.kind) + " elements need " +
                             shape_of(mesh.kind));
        if (!*model)
            throw InputError(group + " has no model");
        typed.push_back(*model);
    }
    return typed;
}

void check_groups(const Mesh& mesh, const std::vector<ElementModel>& group_models)
{
    if (group_models.empty())
        throw InputError("elastic potential: no group models given");
    if (!mesh.group_names.empty() && mesh.group_names.size() != group_models.size())
        throw InputError("elastic potential: the mesh has " + std::to_string(mesh.group_names.size()) +
                         " element groups but " + std::to_string(group_models.size()) + " models are given");
    if (static_cast<int>(mesh.element_groups.size()) != mesh.num_elements())
        throw InputError("elastic potential: the mesh has " + std::to_string(mesh.num_elements()) +
                         " elements but " + std::to_string(mesh.element_groups.size()) + " group indices");
    for (int e = 0; e < mesh.num_elements(); ++e) {
        const int g = mesh.element_groups[e];
        if (g < 0 || g >= static_cast<int>(group_models.size()))
            throw InputError(element_label(e) + " has group index " + std::to_string(g) + ", outside [0, " +
                             std::to_string(group_models.size()) + ")");
    }
}

std::unique_ptr<detail::ElasticElements> make_elements(const Mesh& mesh, const std::vector<ElementModel>& models)
{
    check_mesh_arrays(mesh, "elastic potential");
    check_groups(mesh, models);
    switch (mesh.kind) {
    case ElementKind::tetrahedron:
        return std::make_unique<TypedElasticElements<3, 3>>(mesh, typed_models<3, 3>(mesh, models));
    case ElementKind::triangle_2d:
        return std::make_unique<TypedElasticElements<2, 2>>(mesh, typed_models<2, 2>(mesh, models));
    case ElementKind::triangle_3d:
        return std::make_unique<TypedElasticElements<3, 2>>(mesh, typed_models<3, 2>(mesh, models));
    }
    throw InputError("elastic potential: unknown element kind");
}

} // namespace

ElasticPotential::ElasticPotential(const Mesh& mesh, std::vector<ElementModel> group_models)
    : kind_(mesh.kind), elements_(make_elements(mesh, group_models))
{
}

ElasticPotential::~ElasticPotential() = default;

int ElasticPotential::dimension() const { return elements_->dimension(); }
int ElasticPotential::num_nodes() const { return elements_->num_nodes(); }
int ElasticPotential::num_elements() const { return elements_->num_elements(); }
int ElasticPotential::num_colors() const { return elements_->num_colors(); }
int ElasticPotential::num_blocks() const { return elements_->num_blocks(); }
const Stencils& ElasticPotential::hessian_stencils() const { return elements_->stencils(); }

double ElasticPotential::value(ConstVectorRef x) { return elements_->value(x); }

void ElasticPotential::add_gradient(ConstVectorRef x, VectorRef gradient) { elements_->add_gradient(x, gradient); }

void ElasticPotential::add_hessian(ConstVectorRef x, Projection projection, const StencilSlots& slots,
                                   VectorRef values)
{
    elements_->add_hessian(x, projection, slots, values);
}

namespace {

void check_element(int element, int count)
{
    if (element < 0 || element >= count)
        throw InputError("elastic potential: element " + std::to_string(element) + " is outside [0, " +
                         std::to_string(count) + ")");
}

void check_unit_interval(double value, int element, const char* what)
{
    if (!(value >= 0.0 && value <= 1.0))
        throw InputError(element_label(element) + ": " + what + " " + std::to_string(value) +
                         " is outside [0, 1]");
}

} // namespace

void ElasticPotential::add_activation_gradient(ConstVectorRef x, const std::vector<int>& elements,
                                               VectorRef gradient) const
{
    if (x.size() != dimension() * num_nodes() || gradient.size() != x.size())
        throw InputError("elastic potential: activation gradient of " + std::to_string(x.size()) + " coordinates into " +
                         std::to_string(gradient.size()) + ", expected " + std::to_string(dimension() * num_nodes()));
    for (const int e : elements)
        check_element(e, num_elements());
    elements_->add_activation_gradient(x, elements, gradient);
}

Eigen::VectorXd ElasticPotential::stress_norms(ConstVectorRef x) const { return elements_->stress_norms(x); }

void ElasticPotential::add_output_data(ConstVectorRef x, OutputArrays& arrays)
{
    const int count = num_elements();
    Eigen::MatrixXd activations(1, count), damages(1, count), fibers(material_dimension(kind_), count);
    for (int e = 0; e < count; ++e) {
        activations(0, e) = activation(e);
        damages(0, e) = damage(e);
        fibers.col(e) = fiber(e);
    }
    arrays.cells["activation"] = activations;
    arrays.cells["damage"] = damages;
    arrays.cells["fiber"] = fibers;
    arrays.cells["stress_norm"] = stress_norms(x).transpose();
}

void ElasticPotential::set_fiber(int element, const Eigen::VectorXd& fiber)
{
    check_element(element, num_elements());
    elements_->set_fiber(element, fiber);
}

void ElasticPotential::set_activation(int element, double activation)
{
    check_element(element, num_elements());
    check_unit_interval(activation, element, "activation");
    elements_->set_activation(element, activation);
}

void ElasticPotential::set_damage(int element, double damage)
{
    check_element(element, num_elements());
    check_unit_interval(damage, element, "damage");
    elements_->set_damage(element, damage);
}

Eigen::VectorXd ElasticPotential::fiber(int element) const
{
    check_element(element, num_elements());
    return elements_->fiber(element);
}

double ElasticPotential::activation(int element) const
{
    check_element(element, num_elements());
    return elements_->activation(element);
}

double ElasticPotential::damage(int element) const
{
    check_element(element, num_elements());
    return elements_->damage(element);
}

} // namespace sinew
