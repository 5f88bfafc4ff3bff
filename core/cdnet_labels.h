// The ground-truth labels of the CDnet change-detection benchmark (changedetection.net), shared
// by its reader (sensors/dataset/cdnet_folder.h), its scores (eval/cdnet_scores.h) and the
// simulator that writes its layout (sim/output/cdnet_writer.h).
#pragma once

namespace novelty::core {

inline constexpr int kCdnetStatic = 0, kCdnetShadow = 50, kCdnetOutsideRoi = 85,
                     kCdnetUnknown = 170, kCdnetMotion = 255;

}  // namespace novelty::core
