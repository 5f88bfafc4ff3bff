// Drawing a view's mesh quad by quad into a target (depth_mesh_warper.h): each quad of source
// pixels (u, r)…(u + 1, r + 1) is two triangles, skipped across depth discontinuities (vertex
// depths differing by more than the factor max_ratio) and z-tested per pixel.
#pragma once

#include "maps/views/mesh_vertices.h"
#include "maps/views/warp_target.h"

namespace novelty::views::mesh {

/// One quad, one pixel at a time: the reference the vectorised rasteriser is tested against, and
/// how a planar block that cannot be drawn as one polygon is drawn (block_rasteriser.h).
void RasteriseQuad(const Vertices& v, int w, int u, int r, float max_ratio, const Target& t);

/// The quads of source row r that are drawn on their own (Vertices::skip is 0), sixteen at a
/// time; the same pixels and values as RasteriseQuad on each of them.
void RasteriseRowVectorised(const Vertices& v, int w, int r, float max_ratio, const Target& t);

}  // namespace novelty::views::mesh
