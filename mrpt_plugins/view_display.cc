#include "mrpt_plugins/view_display.h"

#include <mrpt/opengl/CFrustum.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::mrpt_plugins {

std::string StoreSummary(const views::ReferenceViewStore& store) {
  int decoded = 0;
  for (int j = 0; j < store.size(); ++j) decoded += store.decoded(j);
  char text[200];
  std::snprintf(text, sizeof text, "%d reference views, %.1f MiB", store.size(),
                double(store.BytesUsed()) / (1 << 20));
  std::string s = text;
  if (store.options().decoded_views > 0) {
    std::snprintf(text, sizeof text,
                  " (%d decoded, the rest compact; %ld encodings, %ld decodings)", decoded,
                  store.counts().encoded, store.counts().decoded);
    s += text;
  }
  return s;
}

void AddViewFrusta(const views::ReferenceViewStore& store, const std::vector<double>& badness,
                   mrpt::opengl::CSetOfObjects& o) {
  // Frusta point along their +X: turn the camera's +Z onto it.
  Eigen::Isometry3d cam_from_frustum = Eigen::Isometry3d::Identity();
  cam_from_frustum.linear() << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  for (int j = 0; j < store.size(); ++j) {
    const core::PinholeCamera& c = store.camera(j);
    const double hfov = 2.0 * std::atan(0.5 * c.width / std::abs(c.fx));
    const double vfov = 2.0 * std::atan(0.5 * c.height / std::abs(c.fy));
    auto f = mrpt::opengl::CFrustum::Create(0.01f, 0.08f, float(hfov * 180 / M_PI),
                                            float(vfov * 180 / M_PI), 1.0f, true, false);
    if (badness.empty()) {
      f->setColor_u8(160, 160, 160);
    } else {
      const double u = std::clamp(badness[std::size_t(j)], 0.0, 1.0);
      f->setColor_u8(uint8_t(255 * u), uint8_t(255 * (1 - u)), 40);
    }
    f->setPose(sensors::ToMrpt(store.pose(j) * cam_from_frustum));
    o.insert(f);
  }
}

}  // namespace novelty::mrpt_plugins
