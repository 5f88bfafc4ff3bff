#include "sensors/tracker/led_plate.h"

#include <gtest/gtest.h>

#include <random>

namespace novelty::sensors {
namespace {

Eigen::Isometry3d SomeWorldFromPlate() {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
               Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()).toRotationMatrix();
  t.translation() = Eigen::Vector3d(1.0, -0.5, 1.2);
  return t;
}

LedSample Sample(double time, const LedPlate& plate, const Eigen::Isometry3d& world_from_plate,
                 std::mt19937_64& rng, double noise) {
  std::normal_distribution<double> n(0, noise);
  LedSample s;
  s.time = time;
  for (int k = 0; k < 4; ++k)
    s.leds[k] = world_from_plate * plate.leds[k] + Eigen::Vector3d(n(rng), n(rng), n(rng));
  return s;
}

TEST(LedPlate, NominalPlateFrameIsTheFrameOfItsLeds) {
  const LedPlate plate = LedPlate::Nominal();
  EXPECT_LT((PlateFrameFromLeds(plate.leds).matrix() - Eigen::Matrix4d::Identity()).norm(), 1e-15);
  // Plate x looks along the camera's optical axis, y to the right; a proper rotation; centred
  // 8 cm above the optical centre (camera −Y).
  const Eigen::Isometry3d& m = plate.camera_from_plate;
  EXPECT_LT((m.linear().col(0) - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
  EXPECT_LT((m.linear().col(1) - Eigen::Vector3d::UnitX()).norm(), 1e-15);
  EXPECT_NEAR(m.linear().determinant(), 1.0, 1e-15);
  EXPECT_LT((m * Eigen::Vector3d(0.10, 0.06, 0) - Eigen::Vector3d(0, -0.08, 0)).norm(), 1e-15);
}

TEST(LedPlate, CalibrationFromAStaticIntervalRecoversAnIrregularPlate) {
  LedPlate truth = LedPlate::Nominal();
  truth.leds[1] += Eigen::Vector3d(0.004, -0.003, 0.002);  // LED 2 a little off the corner
  truth.leds[2].x() = 0.003;  // LED 3 not quite perpendicular: plate y is orthogonalised
  truth.leds = [&] {
    // Re-express in the plate frame the LEDs define (LED 3 projected off the x axis).
    const Eigen::Isometry3d f = PlateFrameFromLeds(truth.leds);
    std::array<Eigen::Vector3d, 4> l;
    for (int k = 0; k < 4; ++k) l[k] = f.inverse() * truth.leds[k];
    return l;
  }();
  std::mt19937_64 rng(7);
  std::vector<LedSample> samples;
  for (int i = 0; i < 250; ++i)
    samples.push_back(Sample(i * 0.04, truth, SomeWorldFromPlate(), rng, 0.001));
  const LedPlate plate = CalibratePlateGeometry(samples, truth.camera_from_plate);
  for (int k = 0; k < 4; ++k)
    EXPECT_LT((plate.leds[k] - truth.leds[k]).norm(), 0.0003) << "LED " << k + 1;
  EXPECT_LT(plate.leds[3].norm(), 1e-12);            // origin at LED 4
  EXPECT_LT(plate.leds[0].tail<2>().norm(), 1e-12);  // LED 1 on the x axis
  EXPECT_NEAR(plate.leds[2].z(), 0.0, 1e-12);        // LED 3 in the x-y plane
}

TEST(LedPlate, CalibrationRefusesMissingOrCollinearLeds) {
  std::mt19937_64 rng(8);
  std::vector<LedSample> samples = {Sample(0, LedPlate::Nominal(), SomeWorldFromPlate(), rng, 0)};
  samples[0].leds[2].reset();
  EXPECT_THROW(
      {
        try {
          CalibratePlateGeometry(samples, Eigen::Isometry3d::Identity());
        } catch (const std::runtime_error& e) {
          EXPECT_NE(std::string(e.what()).find("LED 3"), std::string::npos) << e.what();
          throw;
        }
      },
      std::runtime_error);
  LedPlate line = LedPlate::Nominal();
  line.leds[2] = Eigen::Vector3d(-0.1, 0.0, 0.0);
  samples = {Sample(0, line, SomeWorldFromPlate(), rng, 0)};
  EXPECT_THROW(CalibratePlateGeometry(samples, Eigen::Isometry3d::Identity()), std::runtime_error);
}

TEST(LedPlate, FindsTheStaticIntervalBetweenMotions) {
  const LedPlate plate = LedPlate::Nominal();
  std::mt19937_64 rng(9);
  std::vector<LedSample> samples;
  for (int i = 0; i < 300; ++i) {
    Eigen::Isometry3d pose = SomeWorldFromPlate();
    // Moves at 5 cm/s, except during samples 100…174 (3 s) where it stands still.
    const int moving = i < 100 ? i : (i < 175 ? 100 : i - 75);
    pose.translation().x() += 0.002 * moving;
    samples.push_back(Sample(i * 0.04, plate, pose, rng, 0.001));
  }
  samples[20].leds[1].reset();  // a dropout while moving does no harm
  for (int i = 110; i < 170; i += 7) samples[std::size_t(i)].leds[i % 4].reset();  // nor still
  std::string why;
  const auto interval = FindStaticInterval(samples, {}, &why);
  ASSERT_TRUE(interval) << why;
  EXPECT_NEAR(double(interval->first), 100, 4);  // the running mean admits a few moving samples
  EXPECT_NEAR(double(interval->second), 176, 4);
  StaticIntervalOptions strict;
  strict.min_duration = 5.0;
  EXPECT_FALSE(FindStaticInterval(samples, strict, &why));
  EXPECT_NE(why.find("no static interval"), std::string::npos) << why;
}

TEST(LedPlate, CameraFromPlateIsTheMeanOverPosePairs) {
  const Eigen::Isometry3d truth = LedPlate::Nominal().camera_from_plate;
  std::mt19937_64 rng(10);
  std::normal_distribution<double> n(0, 0.002);
  std::vector<std::pair<Eigen::Isometry3d, Eigen::Isometry3d>> pairs;
  for (int i = 0; i < 400; ++i) {
    Eigen::Isometry3d cam = SomeWorldFromPlate();
    cam.translation().y() += 0.01 * i;
    Eigen::Isometry3d plate = cam * truth;
    plate.linear() =
        plate.linear() * Eigen::AngleAxisd(n(rng), Eigen::Vector3d::UnitX()).toRotationMatrix();
    plate.translation() += Eigen::Vector3d(n(rng), n(rng), n(rng));
    pairs.emplace_back(plate, cam);
  }
  const Eigen::Isometry3d estimate = EstimateCameraFromPlate(pairs);
  EXPECT_LT((estimate.translation() - truth.translation()).norm(), 0.0005);
  EXPECT_LT(Eigen::AngleAxisd(estimate.linear().transpose() * truth.linear()).angle(), 0.0005);
  EXPECT_THROW(EstimateCameraFromPlate({}), std::runtime_error);
}

}  // namespace
}  // namespace novelty::sensors
