#include "mrpt_plugins/appearance_map_options.h"

#include <mrpt/config/CConfigFile.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>

namespace novelty::mrpt_plugins {

std::string ConfigSourceName(const mrpt::config::CConfigFileBase& config) {
  const auto* file = dynamic_cast<const mrpt::config::CConfigFile*>(&config);
  return file ? file->getAssociatedFile() : "map definition";
}

MapConfig LoadMapConfig(const mrpt::config::CConfigFileBase& config, const std::string& section,
                        const std::string& source) {
  MapConfig result;
  appearance::AppearanceMapOptions& o = result.map;
  auto& u = o.surprise.update;
  auto& init = o.initial_prior;
  auto& v = o.views;
  // Each key with the field it sets; booleans accept true/false/1/0.
  std::map<std::string, std::function<void(const std::string&)>> keys;
  auto number = [&](double* field) {
    return [field](const std::string& text) {
      std::size_t used = 0;
      double value = 0.0;
      try {
        value = std::stod(text, &used);
      } catch (const std::exception&) {
        throw std::invalid_argument("not a number");
      }
      if (text.find_first_not_of(" \t", used) != std::string::npos || !std::isfinite(value)) {
        throw std::invalid_argument("not a number");
      }
      *field = value;
    };
  };
  auto flag = [](bool* field) {
    return [field](const std::string& text) {
      if (text == "true" || text == "1")
        *field = true;
      else if (text == "false" || text == "0")
        *field = false;
      else
        throw std::invalid_argument("not true/false");
    };
  };
  double angle_deg = v.new_view_angle * 180.0 / M_PI;
  keys["forgetting_factor"] = number(&u.forgetting_factor);
  keys["xi"] = number(&u.xi);
  keys["sigma_min"] = number(&u.sigma_min);
  keys["sigma_max"] = number(&u.sigma_max);
  keys["min_variance"] = number(&u.min_variance);
  keys["initial_alpha"] = number(&init.alpha);
  keys["initial_beta"] = number(&init.beta);
  keys["initial_tau"] = number(&init.tau);
  keys["initial_sigma"] = number(&init.sigma);
  keys["fast_approximations"] = flag(&o.surprise.kl.fast_approximations);
  keys["half_precision"] = flag(&o.half_precision);
  keys["new_view_distance"] = number(&v.new_view_distance);
  keys["new_view_angle_deg"] = number(&angle_deg);
  keys["max_relative_depth_jump"] = number(&v.warp.max_relative_depth_jump);
  keys["depth_tolerance"] = number(&v.blend.depth_tolerance);
  keys["angle_power"] = number(&v.blend.angle_power);
  keys["weight_by_rays"] = flag(&v.selection.weight_by_rays);
  DepthSourceOptions& d = result.depth;
  keys["depth_source"] = [&d](const std::string& text) {
    if (text == "rgbd")
      d.kind = DepthSourceOptions::Kind::kRgbd;
    else if (text == "stereo")
      d.kind = DepthSourceOptions::Kind::kStereo;
    else
      throw std::invalid_argument("not rgbd or stereo");
  };
  double hypotheses = d.stereo.sweep.hypotheses, window = d.stereo.sweep.window;
  keys["stereo_near"] = number(&d.stereo.sweep.near);
  keys["stereo_far"] = number(&d.stereo.sweep.far);
  keys["stereo_hypotheses"] = number(&hypotheses);
  keys["stereo_window"] = number(&window);

  std::vector<std::string> present;
  config.getAllKeys(section, present);
  for (const std::string& key : present) {
    const auto it = keys.find(key);
    const std::string where = source + ": [" + section + "] " + key;
    if (it == keys.end()) throw std::runtime_error(where + ": unknown option");
    std::string text = config.read_string(section, key, "", true);
    // Inline comments (after ';', '#' or "//") are not part of the value.
    for (const char* mark : {";", "#", "//"}) text = text.substr(0, text.find(mark));
    text.erase(text.find_last_not_of(" \t\r") + 1);
    try {
      it->second(text);
    } catch (const std::exception& e) {
      throw std::runtime_error(where + " = '" + text + "': " + e.what());
    }
  }
  v.new_view_angle = angle_deg * M_PI / 180.0;
  d.stereo.sweep.hypotheses = int(hypotheses);
  d.stereo.sweep.window = int(window);
  try {
    u.Check();
    if (!(v.blend.depth_tolerance >= 0.0 && v.blend.angle_power >= 0.0))
      throw std::invalid_argument("depth_tolerance and angle_power must be >= 0, got " +
                                  std::to_string(v.blend.depth_tolerance) + " and " +
                                  std::to_string(v.blend.angle_power));
    stats::CheckNormalGamma(init, "initial prior");
    const auto& sweep = d.stereo.sweep;
    if (!(sweep.near > 0 && sweep.far > sweep.near) || sweep.hypotheses < 2 ||
        double(sweep.hypotheses) != hypotheses || sweep.window < 1 ||
        double(sweep.window) != window) {
      throw std::invalid_argument(
          "stereo: need 0 < stereo_near < stereo_far, whole stereo_hypotheses ≥ 2 and "
          "stereo_window ≥ 1");
    }
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(source + ": [" + section + "] " + e.what());
  }
  return result;
}

appearance::AppearanceMapOptions LoadAppearanceMapOptions(
    const mrpt::config::CConfigFileBase& config, const std::string& section,
    const std::string& source) {
  return LoadMapConfig(config, section, source).map;
}

MapConfig LoadMapConfig(const std::string& path, const std::string& section) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": no such config file");
  const mrpt::config::CConfigFile config(path);
  return LoadMapConfig(config, section, path);
}

appearance::AppearanceMapOptions LoadAppearanceMapOptions(const std::string& path,
                                                          const std::string& section) {
  return LoadMapConfig(path, section).map;
}

}  // namespace novelty::mrpt_plugins
