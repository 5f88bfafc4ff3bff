#include "maps/illumination/invariant_image.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "core/float_image.h"
#include "maps/illumination/gradient_integration.h"
#include "maps/stats/column_medians.h"

namespace novelty::illumination {

namespace {

std::string Name(std::size_t m) {
  return "image " + std::to_string(m);
}

void CheckInputs(const std::vector<cv::Mat>& images, const std::vector<cv::Mat>& coverage,
                 const InvariantImageOptions& o) {
  if (!(o.min_intensity > 0.0 && std::isfinite(o.min_intensity)) || o.min_lightings < 2)
    throw std::invalid_argument(
        "ComputeInvariantImage: options need min_intensity > 0 and min_lightings >= 2");
  if (images.size() < 2)
    throw std::invalid_argument(
        "ComputeInvariantImage: " + std::to_string(images.size()) +
        " image(s): a single lighting gives no invariant image (the median of one image's "
        "gradients is that image's own); at least 2 lightings are needed");
  if (int(images.size()) < o.min_lightings)
    throw std::invalid_argument(
        "ComputeInvariantImage: " + std::to_string(images.size()) +
        " images, fewer than min_lightings = " + std::to_string(o.min_lightings));
  if (!coverage.empty() && coverage.size() != images.size())
    throw std::invalid_argument("ComputeInvariantImage: " + std::to_string(coverage.size()) +
                                " coverage masks for " + std::to_string(images.size()) + " images");
  const cv::Mat& first = images.front();
  for (std::size_t m = 0; m < images.size(); ++m) {
    const cv::Mat& im = images[m];
    const int depth = im.depth(), channels = im.channels();
    if (im.empty() || (depth != CV_8U && depth != CV_16U && depth != CV_32F) ||
        (channels != 1 && channels != 3))
      throw std::invalid_argument("ComputeInvariantImage: " + Name(m) +
                                  " must be a non-empty 8-bit, 16-bit or float image with 1 or "
                                  "3 channels");
    if (im.size() != first.size() || im.type() != first.type())
      throw std::invalid_argument("ComputeInvariantImage: " + Name(m) + " is " +
                                  std::to_string(im.cols) + "x" + std::to_string(im.rows) +
                                  " of type " + std::to_string(im.type()) + ", image 0 " +
                                  std::to_string(first.cols) + "x" + std::to_string(first.rows) +
                                  " of type " + std::to_string(first.type()) +
                                  ": all lightings must be one viewpoint's images of one size");
    if (depth == CV_32F && !cv::checkRange(im))
      throw std::invalid_argument("ComputeInvariantImage: " + Name(m) +
                                  " holds NaN or infinite values; mark invalid pixels in its "
                                  "coverage mask instead");
    if (!coverage.empty() && (coverage[m].type() != CV_8UC1 || coverage[m].size() != first.size()))
      throw std::invalid_argument("ComputeInvariantImage: coverage mask " + std::to_string(m) +
                                  " must be CV_8UC1 of the images' size");
  }
}

// The images as float on the 0…255 scale.
std::vector<cv::Mat> FloatImages(const std::vector<cv::Mat>& images) {
  std::vector<cv::Mat> out;
  for (const cv::Mat& im : images) out.push_back(core::ToFloat255(im));
  return out;
}

// log(max(image, floor)).
cv::Mat ClippedLog(const cv::Mat& image, double floor) {
  cv::Mat out;
  cv::max(image, floor, out);
  cv::log(out, out);
  return out;
}

// Channel c of every image, clipped, in the log domain.
std::vector<cv::Mat> LogChannel(const std::vector<cv::Mat>& images, int c, double floor) {
  std::vector<cv::Mat> logs(images.size());
  for (std::size_t m = 0; m < images.size(); ++m) {
    cv::extractChannel(images[m], logs[m], c);
    logs[m] = ClippedLog(logs[m], floor);
  }
  return logs;
}

// The luminance (channel mean) of every image, clipped, in the log domain.
std::vector<cv::Mat> LogLuminance(const std::vector<cv::Mat>& images, double floor) {
  std::vector<cv::Mat> logs(images.size());
  for (std::size_t m = 0; m < images.size(); ++m) {
    logs[m] = ClippedLog(core::ChannelMean(images[m]), floor);
  }
  return logs;
}

constexpr float kMissing = std::numeric_limits<float>::infinity();

struct MedianGradients {
  cv::Mat gx, gy;
};

// Eq. 6.8-6.9 for one channel: per pixel the median over the images that cover both pixels of
// the difference; 0 where fewer than min_lightings do.
MedianGradients MedianLogGradients(const std::vector<cv::Mat>& logs,
                                   const std::vector<cv::Mat>& coverage, int min_lightings) {
  const int rows = logs.front().rows, cols = logs.front().cols, m_count = int(logs.size());
  MedianGradients g{cv::Mat::zeros(rows, cols, CV_32F), cv::Mat::zeros(rows, cols, CV_32F)};
  cv::parallel_for_(cv::Range(0, rows), [&](const cv::Range& range) {
    std::vector<float> vx(size_t(m_count) * cols), vy(size_t(m_count) * cols);
    for (int y = range.start; y < range.end; ++y) {
      const bool last_row = y + 1 == rows;
      for (int m = 0; m < m_count; ++m) {
        const float* row = logs[m].ptr<float>(y);
        const float* below = last_row ? nullptr : logs[m].ptr<float>(y + 1);
        const uchar* cov = coverage.empty() ? nullptr : coverage[m].ptr<uchar>(y);
        const uchar* cov_below =
            coverage.empty() || last_row ? nullptr : coverage[m].ptr<uchar>(y + 1);
        float* dx = vx.data() + size_t(m) * cols;
        float* dy = vy.data() + size_t(m) * cols;
        for (int x = 0; x + 1 < cols; ++x)
          dx[x] = !cov || (cov[x] && cov[x + 1]) ? row[x + 1] - row[x] : kMissing;
        dx[cols - 1] = kMissing;
        for (int x = 0; x < cols; ++x)
          dy[x] = below && (!cov || (cov[x] && cov_below[x])) ? below[x] - row[x] : kMissing;
      }
      stats::ColumnMedians(vx.data(), m_count, cols, min_lightings, 0.0f, g.gx.ptr<float>(y));
      stats::ColumnMedians(vy.data(), m_count, cols, min_lightings, 0.0f, g.gy.ptr<float>(y));
    }
  });
  return g;
}

cv::Mat CoveredPixels(const std::vector<cv::Mat>& coverage, cv::Size size, int min_lightings) {
  if (coverage.empty()) return cv::Mat(size, CV_8U, cv::Scalar(255));
  cv::Mat count = cv::Mat::zeros(size, CV_16U);
  for (const cv::Mat& c : coverage) cv::add(count, cv::Scalar(1), count, c);
  return count >= min_lightings;
}

// r̂ of one plane (eq. 6.6-6.13) from its log images; its constant makes the illumination
// images average 0 over the covered pixels; 0 where not covered.
cv::Mat InvariantPlane(const std::vector<cv::Mat>& logs, const std::vector<cv::Mat>& coverage,
                       const cv::Mat& covered, int min_lightings) {
  const MedianGradients g = MedianLogGradients(logs, coverage, min_lightings);
  const bool whole_image = cv::countNonZero(covered) == covered.size().area();
  cv::Mat r = whole_image ? IntegrateGradients(g.gx, g.gy)
                          : IntegrateGradientsInRegion(g.gx, g.gy, covered);
  // Each 4-connected part of the covered pixels has its own free constant (the integration
  // ties nothing across parts): each is set so that its illumination images average 0.
  cv::Mat parts;
  const int part_count = whole_image ? 2 : cv::connectedComponents(covered, parts, 4, CV_32S);
  if (whole_image) parts = cv::Mat(covered.size(), CV_32S, cv::Scalar(1));
  std::vector<double> sum(part_count, 0.0), count(part_count, 0.0);
  for (std::size_t m = 0; m < logs.size(); ++m) {
    for (int y = 0; y < r.rows; ++y) {
      const float *l = logs[m].ptr<float>(y), *rr = r.ptr<float>(y);
      const int* part = parts.ptr<int>(y);
      const uchar* cov = coverage.empty() ? nullptr : coverage[m].ptr<uchar>(y);
      for (int x = 0; x < r.cols; ++x) {
        if (part[x] == 0 || (cov && !cov[x])) continue;
        sum[part[x]] += l[x] - rr[x];
        count[part[x]] += 1.0;
      }
    }
  }
  for (int y = 0; y < r.rows; ++y) {
    float* rr = r.ptr<float>(y);
    const int* part = parts.ptr<int>(y);
    for (int x = 0; x < r.cols; ++x)
      if (part[x] != 0 && count[part[x]] > 0) rr[x] += float(sum[part[x]] / count[part[x]]);
  }
  r.setTo(0.0f, covered == 0);
  return r;
}

// Per pixel and channel the median over the covering images of the channel's share of the
// luminance (1 for a black pixel), normalised to mean 1 over the channels; as logs, one plane per
// channel. The shares are taken before clipping, which would whiten dark colours.
std::vector<cv::Mat> LogChromaticity(const std::vector<cv::Mat>& images,
                                     const std::vector<cv::Mat>& coverage, const cv::Mat& covered) {
  const cv::Size size = covered.size();
  const int m_count = int(images.size()), cols = size.width;
  std::vector<cv::Mat> out(3);
  for (cv::Mat& o : out) o = cv::Mat::zeros(size, CV_32F);
  cv::parallel_for_(cv::Range(0, size.height), [&](const cv::Range& range) {
    std::vector<float> shares(size_t(3) * m_count * cols), median(size_t(3) * cols);
    for (int y = range.start; y < range.end; ++y) {
      for (int m = 0; m < m_count; ++m) {
        const cv::Vec3f* p = images[m].ptr<cv::Vec3f>(y);
        const uchar* cov = coverage.empty() ? nullptr : coverage[m].ptr<uchar>(y);
        for (int x = 0; x < cols; ++x) {
          const float mean = std::max(0.0f, (p[x][0] + p[x][1] + p[x][2]) / 3.0f);
          for (int c = 0; c < 3; ++c) {
            float& share = shares[(size_t(c) * m_count + m) * cols + x];
            if (cov && !cov[x])
              share = kMissing;
            else
              share = mean > 0.0f ? std::max(0.0f, p[x][c]) / mean : 1.0f;
          }
        }
      }
      for (int c = 0; c < 3; ++c)
        stats::ColumnMedians(shares.data() + size_t(c) * m_count * cols, m_count, cols, 1, 1.0f,
                             median.data() + size_t(c) * cols);
      const uchar* inside = covered.ptr<uchar>(y);
      for (int x = 0; x < cols; ++x) {
        if (!inside[x]) continue;
        const float total = median[x] + median[cols + x] + median[2 * cols + x];
        if (!(total > 0.0f)) continue;  // no channel lit in most images: no colour (log 1 = 0)
        // A channel that is black in most images gets the share of a dark but positive one, so
        // that its log stays finite.
        for (int c = 0; c < 3; ++c)
          out[c].at<float>(y, x) =
              std::log(std::max(3.0f * median[size_t(c) * cols + x] / total, 1e-3f));
      }
    }
  });
  return out;
}

}  // namespace

InvariantImage ComputeInvariantImage(const std::vector<cv::Mat>& images,
                                     const std::vector<cv::Mat>& coverage,
                                     const InvariantImageOptions& options) {
  CheckInputs(images, coverage, options);
  const std::vector<cv::Mat> linear = FloatImages(images);
  const double floor = options.min_intensity;
  const int channels = images.front().channels(), m_count = int(images.size());
  InvariantImage out;
  out.covered = CoveredPixels(coverage, images.front().size(), options.min_lightings);
  std::vector<cv::Mat> r_planes(channels);
  if (channels == 3 && options.colour == InvariantImageOptions::Colour::kLuminanceChromaticity) {
    const cv::Mat r_luminance =
        InvariantPlane(LogLuminance(linear, floor), coverage, out.covered, options.min_lightings);
    r_planes = LogChromaticity(linear, coverage, out.covered);
    for (cv::Mat& r : r_planes) {
      r += r_luminance;
      r.setTo(0.0f, out.covered == 0);
    }
  } else {
    for (int c = 0; c < channels; ++c)
      r_planes[c] = InvariantPlane(LogChannel(linear, c, floor), coverage, out.covered,
                                   options.min_lightings);
  }
  cv::merge(r_planes, out.log_invariant);
  // Eq. 6.14, 0 where image m or r̂ does not cover.
  out.log_illumination.resize(m_count);
  for (int m = 0; m < m_count; ++m) {
    out.log_illumination[m] = ClippedLog(linear[m], floor) - out.log_invariant;
    cv::Mat invalid = out.covered == 0;
    if (!coverage.empty()) invalid |= coverage[m] == 0;
    out.log_illumination[m].setTo(cv::Scalar::all(0.0), invalid);
  }
  return out;
}

cv::Mat LogIllumination(const cv::Mat& image, const cv::Mat& log_invariant, double min_intensity) {
  if (image.size() != log_invariant.size() || image.channels() != log_invariant.channels() ||
      log_invariant.depth() != CV_32F ||
      (image.depth() != CV_8U && image.depth() != CV_16U && image.depth() != CV_32F))
    throw std::invalid_argument(
        "LogIllumination: the image must be 8-bit, 16-bit or float with the invariant image's "
        "size and channels");
  if (image.depth() == CV_32F && !cv::checkRange(image))
    throw std::invalid_argument("LogIllumination: the image holds NaN or infinite values");
  return ClippedLog(FloatImages({image}).front(), min_intensity) - log_invariant;
}

cv::Mat LinearImage(const cv::Mat& log_image, const cv::Mat& covered) {
  cv::Mat linear;
  cv::exp(log_image, linear);
  if (!covered.empty()) linear.setTo(cv::Scalar::all(0.0), covered == 0);
  return linear;
}

cv::Mat LinearImage8(const cv::Mat& log_image, const cv::Mat& covered) {
  cv::Mat out;
  LinearImage(log_image, covered).convertTo(out, CV_8U);
  return out;
}

}  // namespace novelty::illumination
