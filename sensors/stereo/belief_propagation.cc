#include "sensors/stereo/belief_propagation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <stdexcept>

#include "core/lanes.h"

namespace novelty::sensors {
namespace {

using namespace core::lanes;  // F16, I16, Load, Min… (core/lanes.h)

enum Direction { kFromLeft = 0, kFromRight = 1, kFromUp = 2, kFromDown = 3 };

// Lane permutations for the message stores that shift by one pixel, and for (de)interleaving.
const I16 kRotateDown = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 0};
const I16 kRotateUp = {15, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14};
const I16 kEvens = {0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30};
const I16 kOdds = {1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31};
const I16 kZipLow = {0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23};
const I16 kZipHigh = {8, 24, 9, 25, 10, 26, 11, 27, 12, 28, 13, 29, 14, 30, 15, 31};

// One pyramid level in a layout for updating sixteen pixels at once. Every row is split by
// column parity — "half" 0 holds x = 0, 2, 4…, half 1 holds x = 1, 3, 5… — since a checkerboard
// half-pass updates every other pixel; pixel x = 2j + half is number j of its half. A half-row is
// stored in blocks of sixteen pixels × all labels, label-major inside the block, so an update of
// sixteen pixels reads and writes whole cache lines in sequence. Block 0 is padding for j = −1,
// and there is room for j = count (messages that leave the image land there, never read).
struct Level {
  int w = 0, h = 0, labels = 0;
  int blocks = 0;  // per half-row, padding included
  std::vector<float> data;
  std::array<std::unique_ptr<float[]>, 4> in;

  Level(int width, int height, int l) : w(width), h(height), labels(l) {
    blocks = 1 + (Count(0) + 1 + kLanes - 1) / kLanes;
    data.assign(Size(), 0.0f);
  }
  int Count(int half) const { return (w - half + 1) / 2; }  // pixels in a half-row
  std::size_t BlockSize() const { return std::size_t(labels) * kLanes; }
  std::size_t Size() const { return std::size_t(h) * 2 * blocks * BlockSize(); }
  // The block holding pixels j … j+15 of a half-row (j a multiple of 16, ≥ −16).
  std::size_t Block(int y, int half, int j) const {
    return ((std::size_t(y) * 2 + half) * blocks + std::size_t((j + kLanes) / kLanes)) *
           BlockSize();
  }
  void AllocateMessages(bool zero) {
    for (auto& m : in) {
      m.reset(new float[Size()]);
      if (zero) std::fill_n(m.get(), Size(), 0.0f);
    }
  }
};

// Writes the 32 values of a natural-order row chunk (x = 32m … 32m+31) as block m+1 of each half.
inline void SplitChunk(F16 a, F16 b, float* half0, float* half1) {
  Store(half0, Shuffle(a, b, kEvens));
  Store(half1, Shuffle(a, b, kOdds));
}

// Per thread: the four outgoing messages of sixteen pixels, label by label.
struct Scratch {
  std::vector<F16> out[4];
  explicit Scratch(int labels) {
    for (auto& o : out) o.resize(std::size_t(labels));
  }
};

// Stores a message vector (label by label, `msg(l)`) for senders j … j+15 whose receivers are the
// same lanes of block `dest`, or — shift ±1 — one lane over, spilling one lane into the block
// before (shift −1) or after (+1). Lanes `keep` (senders past the row's end) leave what is there.
template <class Msg>
void StoreMessage(float* dest, std::size_t block_size, int shift, int labels, I16 keep, Msg msg) {
  const I16 lane = core::lanes::AsInt(core::lanes::Iota());
  for (int l = 0; l < labels; ++l) {
    float* d = dest + std::size_t(l) * kLanes;
    const F16 m = msg(l);
    if (shift == 0) {
      Store(d, Select(keep, Load(d), m));
    } else if (shift < 0) {  // receiver of lane k is lane k − 1
      const F16 r = Shuffle(m, kRotateDown);
      const I16 own = (lane < 15) & ~Shuffle(keep, kRotateDown);
      Store(d, Select(own, r, Load(d)));
      if (!keep[0]) d[int(kLanes) - 1 - int(block_size)] = m[0];  // lane 15 of the block before
    } else {  // receiver of lane k is lane k + 1
      const F16 r = Shuffle(m, kRotateUp);
      const I16 own = (lane > 0) & ~Shuffle(keep, kRotateUp);
      Store(d, Select(own, r, Load(d)));
      if (!keep[15]) d[block_size] = m[15];  // lane 0 of the block after
    }
  }
}

// Sends the messages of pixels j … j+15 of half `half` in row y: the min-sum update of F&H 2006
// with the truncated linear smoothness cost, sixteen pixels per SIMD lane set.
void SendVector(Level& lv, int y, int half, int j, const BeliefPropagationOptions& opt,
                Scratch& s) {
  const int labels = lv.labels;
  const std::size_t p = lv.Block(y, half, j);
  const float* in[4] = {lv.in[0].get() + p, lv.in[1].get() + p, lv.in[2].get() + p,
                        lv.in[3].get() + p};
  const float* data = lv.data.data() + p;
  // Each message excludes what its receiver sent; its minimum survives the distance transform.
  F16 low[4];
  for (auto& v : low) v = F16{} + std::numeric_limits<float>::infinity();
  for (int l = 0; l < labels; ++l) {
    const std::size_t o = std::size_t(l) * kLanes;
    const F16 a = Load(in[0] + o), b = Load(in[1] + o), c = Load(in[2] + o), d = Load(in[3] + o);
    const F16 total = Load(data + o) + a + b + c + d;
    const F16 m[4] = {total - a, total - b, total - c, total - d};
    for (int k = 0; k < 4; ++k) {
      s.out[k][l] = m[k];
      low[k] = Min(low[k], m[k]);
    }
  }
  // Min-convolution with min(s|Δ|, d): forward and backward scans, four chains at once.
  const float sm = opt.smoothness;
  for (int l = 1; l < labels; ++l) {
    for (int k = 0; k < 4; ++k) s.out[k][l] = Min(s.out[k][l], s.out[k][l - 1] + sm);
  }
  for (int l = labels - 2; l >= 0; --l) {
    for (int k = 0; k < 4; ++k) s.out[k][l] = Min(s.out[k][l], s.out[k][l + 1] + sm);
  }
  // Receivers: to the left neighbour the message arrives "from the right", and so on. Left and
  // right neighbours are in the other half: x − 1 is its pixel j − 1 for half 0 and j for half 1;
  // x + 1 is j for half 0 and j + 1 for half 1.
  // Senders past the row's end.
  const I16 keep = core::lanes::Iota() + float(j) >= float(lv.Count(half));
  const std::size_t block = lv.BlockSize();
  const int other = 1 - half;
  const float cap = opt.smoothness_truncation;
  for (int k = 0; k < 4; ++k) {
    float* dest = nullptr;
    int shift = 0;
    if (k == kFromLeft) {  // out[0] excludes what came from the left: it goes left
      dest = lv.in[kFromRight].get() + lv.Block(y, other, j);
      shift = half == 0 ? -1 : 0;
    } else if (k == kFromRight) {
      dest = lv.in[kFromLeft].get() + lv.Block(y, other, j);
      shift = half == 0 ? 0 : 1;
    } else if (k == kFromUp && y > 0) {
      dest = lv.in[kFromDown].get() + lv.Block(y - 1, half, j);
    } else if (k == kFromDown && y + 1 < lv.h) {
      dest = lv.in[kFromUp].get() + lv.Block(y + 1, half, j);
    }
    if (!dest) continue;
    const F16 lo = low[k], hi = low[k] + cap;
    const std::vector<F16>& m = s.out[k];
    StoreMessage(dest, block, shift, labels, keep, [&](int l) { return Min(m[l], hi) - lo; });
  }
}

// One checkerboard half-pass: every pixel of the given parity sends its four messages.
void SendMessages(Level& lv, int parity, const BeliefPropagationOptions& opt) {
  cv::parallel_for_(cv::Range(0, lv.h), [&](const cv::Range& rows) {
    Scratch scratch(lv.labels);
    for (int y = rows.start; y < rows.end; ++y) {
      const int half = (y + parity) & 1;  // x ≡ y + parity (mod 2)
      for (int j = 0; j < lv.Count(half); j += kLanes) SendVector(lv, y, half, j, opt, scratch);
    }
  });
}

Level FirstLevel(const CostVolume& volume, const BeliefPropagationOptions& o) {
  Level lv(volume.width, volume.height, volume.labels);
  const int chunks = lv.blocks - 1;  // natural-order chunks of 32 pixels
  cv::parallel_for_(cv::Range(0, lv.h), [&](const cv::Range& rows) {
    std::vector<float> row(std::size_t(chunks) * 2 * kLanes, 0.0f);  // zero past the row's end
    for (int y = rows.start; y < rows.end; ++y) {
      for (int l = 0; l < lv.labels; ++l) {
        const float* cost = volume.slice(l) + std::size_t(y) * lv.w;
        for (int x = 0; x < lv.w; ++x) {
          row[std::size_t(x)] = o.data_weight * std::min(cost[x], o.data_truncation);
        }
        for (int m = 0; m < chunks; ++m) {
          const std::size_t label = std::size_t(l) * kLanes;
          SplitChunk(Load(&row[std::size_t(m) * 32]), Load(&row[std::size_t(m) * 32 + 16]),
                     &lv.data[lv.Block(y, 0, m * kLanes) + label],
                     &lv.data[lv.Block(y, 1, m * kLanes) + label]);
        }
      }
    }
  });
  return lv;
}

// The next coarser level: data costs summed over 2×2 blocks. Fine pixels x = 2X and 2X + 1 are
// pixel X of half 0 and of half 1, so coarse pixels X in natural order are sums of whole fine
// blocks; pairs of such chunks split into the coarse halves.
Level CoarserLevel(const Level& fine) {
  Level coarse((fine.w + 1) / 2, (fine.h + 1) / 2, fine.labels);
  const int chunks = coarse.blocks - 1;
  cv::parallel_for_(cv::Range(0, coarse.h), [&](const cv::Range& rows) {
    for (int Y = rows.start; Y < rows.end; ++Y) {
      for (int l = 0; l < fine.labels; ++l) {
        const std::size_t label = std::size_t(l) * kLanes;
        // Natural chunk c of the coarse row: fine blocks c of both halves, rows 2Y and 2Y + 1.
        auto chunk = [&](int c) {
          F16 sum = F16{};
          if (c * kLanes >= fine.Count(0)) return sum;
          for (int y = 2 * Y; y < std::min(2 * Y + 2, fine.h); ++y) {
            for (int half = 0; half < 2; ++half) {
              sum += Load(&fine.data[fine.Block(y, half, c * kLanes) + label]);
            }
          }
          return sum;
        };
        for (int m = 0; m < chunks; ++m) {
          SplitChunk(chunk(2 * m), chunk(2 * m + 1),
                     &coarse.data[coarse.Block(Y, 0, m * kLanes) + label],
                     &coarse.data[coarse.Block(Y, 1, m * kLanes) + label]);
        }
      }
    }
  });
  return coarse;
}

// Finer level's initial messages: those of the parent pixel (F&H 2006, sec. 3.3). Fine pixel
// x = 2j + half has parent X = j, whatever the half: fine block b of either half is the parent
// row's natural chunk b, i.e. eight pixels of each coarse half interleaved.
void InheritMessages(const Level& coarse, Level& fine) {
  cv::parallel_for_(cv::Range(0, fine.h), [&](const cv::Range& rows) {
    for (int k = 0; k < 4; ++k) {
      const float* parent = coarse.in[k].get();
      float* child = fine.in[k].get();
      for (int y = rows.start; y < rows.end; ++y) {
        for (int half = 0; half < 2; ++half) {
          std::fill_n(child + fine.Block(y, half, -kLanes), fine.BlockSize(), 0.0f);  // padding
        }
        for (int b = 0; b + 1 < fine.blocks; ++b) {
          // Coarse pixels X = 16b … 16b+15 are pixels 8b … 8b+7 of each coarse half.
          const int j = (8 * b / kLanes) * kLanes;
          const bool high = (8 * b) % kLanes != 0;
          const std::size_t c0 = coarse.Block(y / 2, 0, j), c1 = coarse.Block(y / 2, 1, j);
          const std::size_t f0 = fine.Block(y, 0, b * kLanes), f1 = fine.Block(y, 1, b * kLanes);
          for (int l = 0; l < fine.labels; ++l) {
            const std::size_t o = std::size_t(l) * kLanes;
            const F16 a = Load(parent + c0 + o), c = Load(parent + c1 + o);
            const F16 v = Shuffle(a, c, high ? kZipHigh : kZipLow);
            Store(child + f0 + o, v);
            Store(child + f1 + o, v);
          }
        }
      }
    }
  });
}

// Best label per pixel from the beliefs (data + the four incoming messages), sixteen pixels at a
// time: sub-label vertex of the parabola through the best three, confidence from the margin to
// the best label more than one step away.
void ReadLabels(const Level& lv, const BeliefPropagationOptions& o, Labeling& result) {
  const int labels = lv.labels;
  const float scale = o.data_weight * o.data_truncation;
  const float inf = std::numeric_limits<float>::infinity();
  cv::parallel_for_(cv::Range(0, lv.h), [&](const cv::Range& rows) {
    for (int y = rows.start; y < rows.end; ++y) {
      for (int half = 0; half < 2; ++half) {
        const int count = lv.Count(half);
        for (int j = 0; j < count; j += kLanes) {
          const std::size_t p = lv.Block(y, half, j);
          auto belief = [&](int l) {
            const std::size_t i = p + std::size_t(l) * kLanes;
            return Load(&lv.data[i]) + Load(&lv.in[0][i]) + Load(&lv.in[1][i]) +
                   Load(&lv.in[2][i]) + Load(&lv.in[3][i]);
          };
          F16 best_value = F16{} + inf, best = F16{};
          for (int l = 0; l < labels; ++l) {
            const F16 b = belief(l);
            const I16 better = b < best_value;
            best_value = Select(better, b, best_value);
            best = Select(better, F16{} + float(l), best);
          }
          F16 before = F16{} + inf, after = F16{} + inf, runner_up = F16{} + inf;
          for (int l = 0; l < labels; ++l) {
            const F16 b = belief(l), label = F16{} + float(l);
            before = Select(label == best - 1.0f, b, before);
            after = Select(label == best + 1.0f, b, after);
            const I16 far = (label < best - 1.0f) | (label > best + 1.0f);
            runner_up = Select(far, Min(runner_up, b), runner_up);
          }
          for (int k = 0; k < kLanes && j + k < count; ++k) {
            const int x = 2 * (j + k) + half;
            float refined = best[k];
            if (best[k] > 0 && best[k] + 1 < labels) {  // vertex of the parabola
              const float curvature = before[k] - 2 * best_value[k] + after[k];
              if (curvature > 0) refined += 0.5f * (before[k] - after[k]) / curvature;
            }
            result.label.at<float>(y, x) = refined;
            result.confidence.at<float>(y, x) =
                std::isfinite(runner_up[k]) ? std::min(1.0f, (runner_up[k] - best_value[k]) / scale)
                                            : 1.0f;
          }
        }
      }
    }
  });
}

}  // namespace

Labeling RunBeliefPropagation(const CostVolume& volume, const BeliefPropagationOptions& o) {
  if (volume.width <= 0 || volume.height <= 0 || volume.labels < 2 ||
      volume.cost.size() != size_t(volume.width) * volume.height * volume.labels)
    throw std::invalid_argument("belief propagation: empty or inconsistent cost volume");
  if (o.levels < 1 || o.iterations < 0 || !(o.smoothness >= 0) || !(o.smoothness_truncation >= 0))
    throw std::invalid_argument("belief propagation: levels ≥ 1, iterations ≥ 0, costs ≥ 0");
  std::vector<Level> levels;
  levels.push_back(FirstLevel(volume, o));
  for (int k = 1; k < o.levels && levels.back().w >= 2 && levels.back().h >= 2; ++k) {
    levels.push_back(CoarserLevel(levels.back()));
  }
  for (int k = int(levels.size()) - 1; k >= 0; --k) {
    levels[k].AllocateMessages(k + 1 == int(levels.size()));
    if (k + 1 < int(levels.size())) {
      InheritMessages(levels[k + 1], levels[k]);
      levels[k + 1] = Level(0, 0, 0);  // free the coarse level
    }
    for (int t = 0; t < o.iterations; ++t) SendMessages(levels[k], t & 1, o);
  }
  const Level& lv = levels[0];
  Labeling result{cv::Mat(lv.h, lv.w, CV_32F), cv::Mat(lv.h, lv.w, CV_32F)};
  ReadLabels(lv, o, result);
  return result;
}

}  // namespace novelty::sensors
