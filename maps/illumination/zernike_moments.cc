#include "maps/illumination/zernike_moments.h"

#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::illumination {

namespace {

// All R_nm(ρ) for n ≤ max_order, m ≥ 0 of n's parity, into table[n][m]. With k = (n - m)/2,
//   R_nm(ρ) = (-1)^k ρ^m P_k^(m,0)(1 - 2ρ²)
// and the Jacobi polynomials P_k^(α,0) come from their three-term recurrence in k, which is
// stable on [-1, 1] as for any family of orthogonal polynomials.
std::vector<std::vector<double>> RadialTable(int max_order, double rho) {
  std::vector<std::vector<double>> r(max_order + 1);
  for (int n = 0; n <= max_order; ++n) r[n].assign(n + 1, 0.0);
  const double x = 1.0 - 2.0 * rho * rho;
  double rho_m = 1.0;  // ρ^m
  for (int m = 0; m <= max_order; ++m, rho_m *= rho) {
    const double a = m;
    double previous = 0.0, current = 1.0;  // P_{k-1}, P_k
    for (int k = 0; m + 2 * k <= max_order; ++k) {
      r[m + 2 * k][m] = (k % 2 ? -1.0 : 1.0) * rho_m * current;
      double next;
      if (k == 0) {
        next = (a + 1.0) + (a + 2.0) * (x - 1.0) / 2.0;
      } else {
        const double c = 2.0 * k + a;
        next = ((c + 1.0) * ((c + 2.0) * c * x + a * a) * current -
                2.0 * (k + a) * k * (c + 2.0) * previous) /
               (2.0 * (k + 1) * (k + a + 1.0) * c);
      }
      previous = current;
      current = next;
    }
  }
  return r;
}

}  // namespace

int ZernikeMoments::Count(int max_order) {
  int count = 0;
  for (int n = 0; n <= max_order; ++n) count += n / 2 + 1;
  return count;
}

double ZernikeMoments::Radial(int n, int m, double rho) {
  m = std::abs(m);
  if (n < 0 || m > n || (n - m) % 2)
    throw std::invalid_argument("ZernikeMoments::Radial: need n >= |m| and n - |m| even");
  return RadialTable(n, rho)[n][m];
}

ZernikeMoments::ZernikeMoments(const ZernikeOptions& options) : options_(options) {
  if (options.max_order < 0 || options.max_order > 200 || options.grid < 2 || options.grid > 512)
    throw std::invalid_argument(
        "ZernikeMoments: max_order must be in [0, 200] and grid in [2, 512]");
  const int g = options.grid, order = options.max_order;
  for (int n = 0; n <= order; ++n)
    for (int m = n % 2; m <= n; m += 2) orders_.push_back({n, m});
  // Cell centres on [-1, 1]², the square around the unit disc; cells outside the disc are
  // left out (ring -1).
  const double step = 2.0 / g, area = step * step;
  std::map<long, int> ring_of_key;  // integer key of ρ² on the cell lattice
  std::vector<double> ring_rho;
  ring_of_cell_.resize(size_t(g) * g);
  phase_.resize(size_t(g) * g * (order + 1));
  for (int y = 0; y < g; ++y) {
    for (int x = 0; x < g; ++x) {
      const int ix = 2 * x + 1 - g, iy = 2 * y + 1 - g;  // centre in half-cells, exact
      const long key = long(ix) * ix + long(iy) * iy;
      if (key > long(g) * g) {  // ρ > 1
        ring_of_cell_[size_t(y) * g + x] = -1;
        continue;
      }
      auto [it, inserted] = ring_of_key.emplace(key, int(ring_rho.size()));
      if (inserted) ring_rho.push_back(std::sqrt(double(key)) * step / 2.0);
      ring_of_cell_[size_t(y) * g + x] = it->second;
      // Image rows grow downwards; θ is measured from the u axis towards v = -row.
      const double theta = std::atan2(-double(iy), double(ix));
      for (int m = 0; m <= order; ++m)
        phase_[(size_t(y) * g + x) * (order + 1) + m] = std::polar(area, -m * theta);
    }
  }
  rings_ = int(ring_rho.size());
  radial_.resize(orders_.size() * rings_);
  for (int r = 0; r < rings_; ++r) {
    const auto table = RadialTable(order, ring_rho[r]);
    for (size_t k = 0; k < orders_.size(); ++k)
      radial_[k * rings_ + r] = table[orders_[k].first][orders_[k].second];
  }
}

std::vector<std::complex<double>> ZernikeMoments::Moments(const cv::Mat& shape) const {
  if (shape.empty() || shape.channels() != 1)
    throw std::invalid_argument("ZernikeMoments: the shape must be a non-empty one-channel image");
  const int g = options_.grid, order = options_.max_order;
  cv::Mat f;
  shape.convertTo(f, CV_64F,
                  shape.depth() == CV_8U    ? 1.0 / 255.0
                  : shape.depth() == CV_16U ? 1.0 / 65535.0
                                            : 1.0);
  std::vector<std::complex<double>> moments(orders_.size());
  // [KH90]: the shape's centroid at the disc's centre, its farthest pixel corner on the rim —
  // translation and scale drop out, and the magnitudes are left unchanged by a rotation.
  const cv::Moments mo = cv::moments(f);
  if (!(mo.m00 > 0.0)) return moments;  // empty: all 0
  const double cx = mo.m10 / mo.m00, cy = mo.m01 / mo.m00;
  double radius = 0.0;
  for (int y = 0; y < f.rows; ++y)
    for (int x = 0; x < f.cols; ++x)
      if (f.at<double>(y, x) != 0.0) radius = std::max(radius, std::hypot(x - cx, y - cy));
  radius += M_SQRT1_2;  // to the pixel's far corner
  // Resample the disc's square onto the cells: area-averaged first where a cell spans several
  // pixels, then an exact affine map of cell centres to pixel positions.
  double scale = 1.0;                           // pixels of `f` per original pixel
  const double cell_pixels = 2.0 * radius / g;  // original pixels per cell
  if (cell_pixels > 1.0) {
    scale = 1.0 / cell_pixels;
    // A thin shape (a line one pixel high, 200 long) would shrink to no row at all: zeros below
    // and to the right change neither its moments nor its pixel positions.
    const int min_side = int(std::ceil(cell_pixels)) + 1;
    if (f.rows < min_side || f.cols < min_side)
      cv::copyMakeBorder(f, f, 0, std::max(0, min_side - f.rows), 0, std::max(0, min_side - f.cols),
                         cv::BORDER_CONSTANT, cv::Scalar(0));
    cv::resize(f, f, cv::Size(), scale, scale, cv::INTER_AREA);
  }
  // Cell (x, y) centre → pixel of f: (cx + (-1 + (x + 0.5) 2/g) R) · scale, likewise y.
  const double pitch = 2.0 * radius / g * scale;
  const double offset = 0.5 * pitch - 0.5 * (1.0 - scale);
  const cv::Matx23d cell_to_pixel(pitch, 0.0, (cx - radius) * scale + offset, 0.0, pitch,
                                  (cy - radius) * scale + offset);
  cv::Mat cells;
  cv::warpAffine(f, cells, cell_to_pixel, {g, g}, cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                 cv::BORDER_CONSTANT, cv::Scalar(0.0));
  // Per ring and m: Σ f e^{-imθ} ΔA.
  std::vector<std::complex<double>> ring_sums(size_t(rings_) * (order + 1));
  for (int y = 0; y < g; ++y) {
    const double* row = cells.ptr<double>(y);
    for (int x = 0; x < g; ++x) {
      const size_t cell = size_t(y) * g + x;
      if (row[x] == 0.0 || ring_of_cell_[cell] < 0) continue;
      const std::complex<double>* phase = &phase_[cell * (order + 1)];
      std::complex<double>* sum = &ring_sums[size_t(ring_of_cell_[cell]) * (order + 1)];
      for (int m = 0; m <= order; ++m) sum[m] += row[x] * phase[m];
    }
  }
  for (size_t k = 0; k < orders_.size(); ++k) {
    const auto [n, m] = orders_[k];
    const double* radial = &radial_[k * rings_];
    std::complex<double> a = 0.0;
    for (int r = 0; r < rings_; ++r) a += radial[r] * ring_sums[size_t(r) * (order + 1) + m];
    moments[k] = (n + 1) / M_PI * a;  // eq. 6.21
  }
  return moments;
}

std::vector<float> ZernikeMoments::Magnitudes(const cv::Mat& shape) const {
  const auto moments = Moments(shape);
  std::vector<float> d(moments.size());
  for (size_t k = 0; k < moments.size(); ++k) d[k] = float(std::abs(moments[k]));
  return d;
}

double DescriptorDistance(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size())
    throw std::invalid_argument("DescriptorDistance: descriptors of different lengths");
  double sum = 0.0;
  for (size_t k = 0; k < a.size(); ++k) sum += double(a[k] - b[k]) * (a[k] - b[k]);
  return std::sqrt(sum);
}

}  // namespace novelty::illumination
