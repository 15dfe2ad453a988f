#include "sinew/bench/kernel_benchmark.hpp"

#include "sinew/energies/models/model_catalog.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <random>

namespace sinew {
namespace {

/// A uniformly random rotation of R^N (N = 2 or 3).
template <int N>
Eigen::Matrix<double, N, N> random_rotation(std::mt19937& rng)
{
    std::normal_distribution<double> normal;
    if constexpr (N == 3) {
        Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
        return q.normalized().toRotationMatrix();
    } else {
        const double angle = std::atan2(normal(rng), normal(rng));
        return Eigen::Rotation2Dd(angle).toRotationMatrix();
    }
}

template <int Rows, int Cols>
KernelRun run(const std::string& name, const std::string& shape, long evaluations, unsigned seed)
{
    using Model = ConstitutiveModel<Rows, Cols>;
    const auto model = make_model<Rows, Cols>(name, ParameterValues{});
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> stretch(0.5, 2.0), unit(0.0, 1.0);
    std::normal_distribution<double> normal;

    std::vector<typename Model::Deformation> deformations(static_cast<size_t>(evaluations));
    std::vector<typename Model::Point> points(static_cast<size_t>(evaluations));
    for (long e = 0; e < evaluations; ++e) {
        Eigen::Matrix<double, Rows, Cols> sigma = Eigen::Matrix<double, Rows, Cols>::Zero();
        for (int i = 0; i < Cols; ++i)
            sigma(i, i) = stretch(rng);
        deformations[static_cast<size_t>(e)] =
            random_rotation<Rows>(rng) * sigma * random_rotation<Cols>(rng).transpose();
        typename Model::Point& point = points[static_cast<size_t>(e)];
        for (int i = 0; i < Cols; ++i)
            point.fiber[i] = normal(rng);
        point.fiber.normalize();
        point.activation = unit(rng);
        point.damage = unit(rng);
    }

    // In batches, as the elastic potential's assembly calls the models.
    constexpr int kBatch = 16;
    typename Model::Stress P[kBatch];
    typename Model::Stiffness dPdF[kBatch];
    double psi[kBatch];
    double checksum = 0.0;
    const auto start = std::chrono::steady_clock::now();
    for (long first = 0; first < evaluations; first += kBatch) {
        const int count = static_cast<int>(std::min<long>(kBatch, evaluations - first));
        const size_t k = static_cast<size_t>(first);
        model->evaluate_batch(count, &deformations[k], &points[k], psi, P, dPdF, Projection::clamp);
        for (int i = 0; i < count; ++i)
            checksum += psi[i] + P[i].sum() + dPdF[i].sum();
    }
    const double time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    KernelRun result;
    result.model = name;
    result.shape = shape;
    result.evaluations = evaluations;
    result.time_s = time_s;
    result.evaluations_per_second = static_cast<double>(evaluations) / time_s;
    result.checksum = checksum;
    return result;
}

} // namespace

std::vector<KernelRun> run_kernel_benchmarks(long evaluations, unsigned seed)
{
    std::vector<KernelRun> runs;
    for (const ModelEntry& entry : model_catalog())
        for (const std::string& shape : entry.shapes()) {
            if (shape == "3x3")
                runs.push_back(run<3, 3>(entry.name, shape, evaluations, seed));
            else if (shape == "2x2")
                runs.push_back(run<2, 2>(entry.name, shape, evaluations, seed));
            else
                runs.push_back(run<3, 2>(entry.name, shape, evaluations, seed));
        }
    return runs;
}

} // namespace sinew
