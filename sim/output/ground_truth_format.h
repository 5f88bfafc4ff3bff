// The ground-truth format's constants, shared by its writer and its reader (the layout of the
// files is documented in ground_truth_writer.h).
#pragma once

namespace novelty::sim::ground_truth {

inline constexpr double kDepthUnitsPerMetre = 5000.0;  ///< depth/*.png: uint16 = metres × 5000
inline constexpr int kIdOffset = 1;          ///< ids/*.png: object id + 1 (0 = no surface)
inline constexpr int kNoveltyAdded = 255;    ///< novelty/*.png: an added (or moved) object, the arm
inline constexpr int kNoveltyRemoved = 128;  ///< … where a removed (or moved) object was
inline constexpr int kArmId = 1000;          ///< the person's arm in ids/ and objects.csv

}  // namespace novelty::sim::ground_truth
