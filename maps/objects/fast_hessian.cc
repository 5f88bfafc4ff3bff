#include "maps/objects/fast_hessian.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>

#include "maps/objects/box_filters.h"

namespace novelty::objects {

namespace {

// Filter side of interval i (0…3) in octave o.
int FilterSize(int octave, int interval) {
  return 3 * ((2 << octave) * (interval + 1) + 1);
}

// det H and the trace's sign of one filter size over one octave's sampling grid.
struct Layer {
  int size = 0;
  cv::Mat det;        // CV_32F, grid rows × cols
  cv::Mat laplacian;  // CV_8S
};

// The samples (rows, columns of a grid of `step` px) whose image position lies in `area`.
struct SampleRange {
  cv::Range rows, cols;
};

SampleRange SamplesIn(const cv::Rect& area, int step, int rows, int cols) {
  const auto first = [step](int px) { return (px + step - 1) / step; };
  const auto last = [step](int px) { return px / step; };
  return {
      cv::Range(std::min(first(area.y), rows), std::min(last(area.y + area.height - 1) + 1, rows)),
      cv::Range(std::min(first(area.x), cols), std::min(last(area.x + area.width - 1) + 1, cols))};
}

// det H and the trace's sign at the samples of `in`; 0 elsewhere (below any threshold).
Layer ComputeLayer(const cv::Mat& integral, int size, int step, int rows, int cols,
                   const SampleRange& in) {
  Layer l;
  l.size = size;
  l.det = cv::Mat::zeros(rows, cols, CV_32F);
  l.laplacian = cv::Mat::zeros(rows, cols, CV_8S);
  cv::parallel_for_(in.rows, [&](const cv::Range& range) {
    for (int r = range.start; r < range.end; ++r) {
      float* det = l.det.ptr<float>(r);
      schar* laplacian = l.laplacian.ptr<schar>(r);
      for (int c = in.cols.start; c < in.cols.end; ++c) {
        int sign = 0;
        det[c] = HessianDeterminant(integral, r * step, c * step, size, &sign);
        laplacian[c] = schar(sign);
      }
    }
  });
  return l;
}

// Every second sample of a layer of the octave before: octave o + 1's first two filter sizes are
// octave o's second and fourth (15 and 27 at o = 0, …), evaluated at every second pixel of it.
Layer EverySecond(const Layer& finer, int rows, int cols) {
  Layer l;
  l.size = finer.size;
  l.det.create(rows, cols, CV_32F);
  l.laplacian.create(rows, cols, CV_8S);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      l.det.at<float>(r, c) = finer.det.at<float>(2 * r, 2 * c);
      l.laplacian.at<schar>(r, c) = finer.laplacian.at<schar>(2 * r, 2 * c);
    }
  }
  return l;
}

bool IsMaximum(const Layer& b, const Layer& m, const Layer& t, int r, int c) {
  const float v = m.det.at<float>(r, c);
  for (const Layer* l : {&b, &m, &t}) {
    for (int dr = -1; dr <= 1; ++dr) {
      for (int dc = -1; dc <= 1; ++dc) {
        if (l == &m && dr == 0 && dc == 0) continue;
        if (l->det.at<float>(r + dr, c + dc) >= v) return false;
      }
    }
  }
  return true;
}

// The quadratic's offset (column, row, interval) from the sample maximum (Brown & Lowe 2002);
// false if the fit is degenerate or puts the maximum a sample or more away. Offsets of 0.5 to 1
// are kept, as OpenCV's SURF keeps them: the neighbour is not a sample maximum (3×3×3), so the
// point is found once either way, and OpenSURF's cut at 0.5 drops about a sixth of the maxima —
// which ones depends on how the image is sampled, so a turned copy loses others (graf1 crop,
// 30°: repeatability 0.44 with the cut, 0.49 without).
bool Interpolate(const Layer& b, const Layer& m, const Layer& t, int r, int c,
                 Eigen::Vector3d& offset) {
  auto M = [&](int dr, int dc) { return double(m.det.at<float>(r + dr, c + dc)); };
  auto T = [&](int dr, int dc) { return double(t.det.at<float>(r + dr, c + dc)); };
  auto B = [&](int dr, int dc) { return double(b.det.at<float>(r + dr, c + dc)); };
  const double v = M(0, 0);
  const Eigen::Vector3d d((M(0, 1) - M(0, -1)) / 2, (M(1, 0) - M(-1, 0)) / 2,
                          (T(0, 0) - B(0, 0)) / 2);
  const double dxx = M(0, 1) + M(0, -1) - 2 * v, dyy = M(1, 0) + M(-1, 0) - 2 * v,
               dss = T(0, 0) + B(0, 0) - 2 * v;
  const double dxy = (M(1, 1) - M(1, -1) - M(-1, 1) + M(-1, -1)) / 4;
  const double dxs = (T(0, 1) - T(0, -1) - B(0, 1) + B(0, -1)) / 4;
  const double dys = (T(1, 0) - T(-1, 0) - B(1, 0) + B(-1, 0)) / 4;
  Eigen::Matrix3d h;
  h << dxx, dxy, dxs, dxy, dyy, dys, dxs, dys, dss;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(h);
  if (!lu.isInvertible()) return false;
  offset = -lu.solve(d);
  return offset.allFinite() && offset.cwiseAbs().maxCoeff() < 1.0;
}

}  // namespace

float HessianDeterminant(const cv::Mat& integral, int row, int col, int size, int* laplacian) {
  const int b = (size - 1) / 2, l = size / 3;  // border, lobe
  const double dxx = BoxSum(integral, row - l + 1, col - b, 2 * l - 1, size) -
                     3.0 * BoxSum(integral, row - l + 1, col - l / 2, 2 * l - 1, l);
  const double dyy = BoxSum(integral, row - b, col - l + 1, size, 2 * l - 1) -
                     3.0 * BoxSum(integral, row - l / 2, col - l + 1, l, 2 * l - 1);
  // −∂²/∂x∂y (the sign does not matter: only Dxy² enters).
  const double dxy =
      BoxSum(integral, row - l, col + 1, l, l) + BoxSum(integral, row + 1, col - l, l, l) -
      BoxSum(integral, row - l, col - l, l, l) - BoxSum(integral, row + 1, col + 1, l, l);
  const double area = double(size) * size;  // normalises the response to the filter size
  if (laplacian) *laplacian = dxx + dyy >= 0.0 ? 1 : -1;
  return float((dxx * dyy - 0.81 * dxy * dxy) / (area * area));  // Bay eq. 4, w = 0.9
}

std::vector<HessianPoint> DetectFastHessian(const cv::Mat& integral,
                                            const FastHessianOptions& options,
                                            const cv::Rect& region) {
  if (integral.type() != CV_64FC1 || integral.rows < 2 || integral.cols < 2)
    throw std::invalid_argument("DetectFastHessian: expected a CV_64F integral image");
  if (!(options.threshold >= 0.0) || options.octaves < 1 || options.octaves > 8 ||
      options.init_step < 1 || options.init_step > 8)
    throw std::invalid_argument(
        "DetectFastHessian: threshold must be >= 0, octaves in 1..8, "
        "init_step in 1..8");
  const int height = integral.rows - 1, width = integral.cols - 1;
  const cv::Rect image(0, 0, width, height);
  const cv::Rect searched = region.empty() ? image : region & image;
  // A maximum found at a sample within one step of `searched` (its refined position may round
  // into it) reads its neighbours and their neighbours, two steps out, at most 2·(init_step <<
  // (octaves − 1)) px; and octave o + 1 reads octave o's layers at its own samples. Responses
  // within three coarsest steps of `searched` serve every octave exactly as the whole image.
  const int margin = 3 * (options.init_step << (options.octaves - 1));
  const cv::Rect computed =
      region.empty() ? image
                     : cv::Rect(searched.x - margin, searched.y - margin,
                                searched.width + 2 * margin, searched.height + 2 * margin) &
                           image;
  std::vector<HessianPoint> points;
  std::vector<Layer> layers;  // this octave's four, after the octave before's
  for (int o = 0; o < options.octaves; ++o) {
    const int step = options.init_step << o;
    const int rows = height / step, cols = width / step;
    // A maximum of interval 1 or 2 needs the filter above it inside the image, and a neighbour
    // beyond that.
    const auto bound_of = [&](int i) { return (FilterSize(o, i + 1) + 1) / (2 * step) + 1; };
    if (rows <= 2 * bound_of(1) || cols <= 2 * bound_of(1)) break;
    std::vector<Layer> finer = std::move(layers);
    layers.clear();
    for (int i = 0; i < 4; ++i) {
      if (o > 0 && i < 2) {
        layers.push_back(EverySecond(finer[std::size_t(2 * i + 1)], rows, cols));
      } else {
        layers.push_back(ComputeLayer(integral, FilterSize(o, i), step, rows, cols,
                                      SamplesIn(computed, step, rows, cols)));
      }
    }
    for (int i = 1; i <= 2; ++i) {
      const Layer &b = layers[i - 1], &m = layers[i], &t = layers[i + 1];
      const int bound = bound_of(i);
      const cv::Rect near(searched.x - step, searched.y - step, searched.width + 2 * step,
                          searched.height + 2 * step);
      const SampleRange candidates = SamplesIn(near & image, step, rows, cols);
      for (int r = std::max(bound, candidates.rows.start);
           r < std::min(rows - bound, candidates.rows.end); ++r) {
        for (int c = std::max(bound, candidates.cols.start);
             c < std::min(cols - bound, candidates.cols.end); ++c) {
          const float v = m.det.at<float>(r, c);
          if (!(v > options.threshold) || !IsMaximum(b, m, t, r, c)) continue;
          Eigen::Vector3d offset;
          if (!Interpolate(b, m, t, r, c, offset)) continue;
          HessianPoint p;
          p.pt = cv::Point2f(float((c + offset.x()) * step), float((r + offset.y()) * step));
          p.scale = float(1.2 / 9.0 * (m.size + offset.z() * (m.size - b.size)));
          p.response = v;
          p.laplacian = m.laplacian.at<schar>(r, c);
          p.octave = o;
          points.push_back(p);
        }
      }
    }
  }
  return points;
}

}  // namespace novelty::objects
