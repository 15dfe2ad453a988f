#pragma once
#include <string>
#include <vector>

namespace sinew {

/// Throughput of one constitutive model: ψ + P + PSD-projected ∂P/∂F per
/// evaluation, on one core, over distinct random deformation gradients, in
/// batches of 16 through ConstitutiveModel::evaluate_batch (as the assembly
/// of the elastic potential calls it).
struct KernelRun {
    std::string model;
    std::string shape;  ///< "3x3", "2x2", "3x2"
    long evaluations = 0;
    double time_s = 0.0;
    double evaluations_per_second = 0.0;
    /// Sum of ψ and of every entry of P and ∂P/∂F: keeps the compiler from
    /// dropping the work, and is not finite when any output was not; `sinew
    /// bench` then reports the model as failed instead of timing it.
    double checksum = 0.0;
};

/// Every model of the catalog, at its default parameters, in every shape it
/// takes; `evaluations` distinct F drawn before the clock starts:
/// F = R₁·diag(σ)·R₂ᵀ with random rotations and σ uniform in [0.5, 2], random
/// unit fibers, activation and damage uniform in [0, 1].
std::vector<KernelRun> run_kernel_benchmarks(long evaluations, unsigned seed);

} // namespace sinew
