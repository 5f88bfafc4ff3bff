// Medians down the columns of a small stack of rows: for each column x, the median of the M
// values rows[0][x] … rows[M-1][x]. The illumination-invariant map takes the median over M
// lightings of every pixel's log-gradients (eq. 6.8-6.9) and colour shares; done a row at a
// time with a sorting network whose compare-exchanges run over whole rows, the compiler
// vectorises it, where a sort per pixel branches on every value.
#pragma once

namespace novelty::stats {

/// `values`: `rows` rows of `width` floats, row m at values + m·width; reordered in place (each
/// column ends sorted). A value of +infinity marks it missing. out[x] is the median of column x's
/// present values — for an even count the mean of the two middle ones (as NumPy's) — or
/// `missing` where fewer than `min_count` are present. rows ≥ 1, min_count ≥ 1.
void ColumnMedians(float* values, int rows, int width, int min_count, float missing, float* out);

}  // namespace novelty::stats
