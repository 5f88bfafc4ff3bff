#include "sensors/localization/support_views.h"

#include <stdexcept>
#include <string>

namespace novelty::sensors {

SupportViews LocalizeSupportViews(const DirectOdometry& common,
                                  const std::vector<StereoPair>& frames,
                                  const std::vector<Eigen::Isometry3d>& own_from_camera,
                                  const SupportViewOptions& options,
                                  const std::optional<Eigen::Isometry3d>& first_prior) {
  if (frames.size() != own_from_camera.size())
    throw std::invalid_argument("LocalizeSupportViews: " + std::to_string(frames.size()) +
                                " frames but " + std::to_string(own_from_camera.size()) +
                                " own poses");
  if (options.every < 1)
    throw std::invalid_argument("LocalizeSupportViews: 'every' must be at least 1, got " +
                                std::to_string(options.every));
  SupportViews out;
  if (frames.empty()) return out;
  // The latest estimate of Q = S·M⁻¹ (eq. 6.1), from the prior until a support view is found.
  std::optional<Eigen::Isometry3d> q;
  if (first_prior) q = *first_prior * own_from_camera.front().inverse();
  for (std::size_t j = 0; j < frames.size(); j += std::size_t(options.every)) {
    std::optional<Eigen::Isometry3d> prior;
    if (q) prior = *q * own_from_camera[j];
    std::string why;
    const auto pose = common.Localize(frames[j], &why, prior);
    if (!pose) {
      out.skipped.push_back("frame " + std::to_string(j) + ": " + why);
      continue;
    }
    out.views.push_back({double(j), *pose, own_from_camera[j]});
    q = *pose * own_from_camera[j].inverse();
  }
  return out;
}

}  // namespace novelty::sensors
