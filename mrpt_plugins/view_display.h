// What a view-based map shows of itself: the summary asString gives and the frusta
// getVisualizationInto draws.
#pragma once

#include <mrpt/opengl/CSetOfObjects.h>

#include <string>
#include <vector>

#include "maps/views/reference_view_store.h"

namespace novelty::mrpt_plugins {

/// "N reference views, X MiB", and for a compact store how many are decoded and how often
/// views were encoded and decoded: what asString says of a view-based map.
std::string StoreSummary(const views::ReferenceViewStore& store);

/// One frustum per reference view at its pose; `badness[j]` in [0, 1] colours view j from green
/// to red (empty: all grey).
void AddViewFrusta(const views::ReferenceViewStore& store, const std::vector<double>& badness,
                   mrpt::opengl::CSetOfObjects& o);

}  // namespace novelty::mrpt_plugins
