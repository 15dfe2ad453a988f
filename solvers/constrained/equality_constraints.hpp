#pragma once
#include "sinew/problems/nlp.hpp"
#include "sinew/solvers/constrained/constraint_residuals.hpp"

#include <optional>
#include <string>

namespace sinew {

/// The constraints of an NLP whose constraints are all equalities: their
/// residuals c̃(x) = c(x) − g_L are ConstraintResiduals::residuals(), the
/// violation c − P(c) of the general rows (kkt-newton).
using EqualityConstraints = ConstraintResiduals;

/// Why a strategy for equality constraints and bounds cannot take `nlp`
/// (inequality constraints: naming the strategies that take them; neither
/// constraints nor bounds: naming projected Newton, the same Newton without
/// the strategy); nothing when it can.
std::optional<std::string> refuse_inequalities(const std::string& solver, const Nlp& nlp);

/// Why a strategy for constraints and bounds (equalities and inequalities)
/// cannot take `nlp`: neither constraints nor bounds, naming projected
/// Newton; nothing when it can.
std::optional<std::string> refuse_unconstrained(const std::string& solver, const Nlp& nlp);

} // namespace sinew
