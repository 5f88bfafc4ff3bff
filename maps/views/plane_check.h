// What a map read from a file must hold before it is used: each view a plane of the given name,
// channel count and values. A map file is outside data: a NaN or a zero where the model divides
// would poison every prediction from that view on, silently.
#pragma once

#include <string>
#include <vector>

#include "maps/views/reference_view_store.h"

namespace novelty::views {

enum class PlaneValues {
  kPositive,     ///< every value finite and > 0 (normal-gamma α, β, σ)
  kFinite,       ///< every value finite (τ)
  kFiniteOrNaN,  ///< finite, or NaN for "unknown" (a colour where the depth was unknown)
};

struct PlaneRule {
  std::string name;
  int channels;
  PlaneValues values;
};

/// Throws std::invalid_argument "view J: plane NAME …" unless every view of `store` has, for
/// each rule, plane `name` with `channels` channels of float or half-float values obeying
/// `values`. Each view is decoded once (a compact store's views one at a time).
void CheckPlanes(const ReferenceViewStore& store, const std::vector<PlaneRule>& rules);

}  // namespace novelty::views
