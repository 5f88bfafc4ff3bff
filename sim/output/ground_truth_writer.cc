#include "sim/output/ground_truth_writer.h"

#include "core/frame_stem.h"
#include "core/write_rgb_image.h"
#include "sim/output/ground_truth_format.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <stdexcept>

namespace novelty::sim {

GroundTruthWriter::GroundTruthWriter(const std::string& dir, const Scenario& scenario,
                                     const std::vector<Eigen::Isometry3d>& rig_offsets)
    : dir_(dir + "/groundtruth"), scenario_(scenario) {
  for (const char* sub : {"depth", "ids", "novelty"}) {
    std::filesystem::create_directories(dir_ + "/" + sub);
  }
  poses_.open(dir_ + "/poses.csv");
  if (!poses_) throw std::runtime_error(dir_ + "/poses.csv: cannot open for writing");
  poses_ << "frame,time,phase,x,y,z,qx,qy,qz,qw,robot_x,robot_y,robot_phi,odo_x,odo_y,odo_phi\n";
  poses_.precision(9);
  std::ofstream rig(dir_ + "/rig.csv");
  rig << "camera,width,height,fx,fy,cx,cy,tx,ty,tz\n";
  const core::PinholeCamera& c = scenario.camera;
  for (std::size_t i = 0; i < rig_offsets.size(); ++i) {
    const Eigen::Vector3d t = rig_offsets[i].translation();
    rig << i << "," << c.width << "," << c.height << "," << c.fx << "," << c.fy << "," << c.cx
        << "," << c.cy << "," << t.x() << "," << t.y() << "," << t.z() << "\n";
  }
  std::ofstream format(dir_ + "/format.txt");
  format << "Ground truth of scenario '" << scenario.name << "' (" << scenario.file << ").\n"
         << "poses.csv: true T_world_cam of the reference camera per frame (translation, unit\n"
         << "  quaternion), with the true robot pose and its odometry in the plane.\n"
         << "rig.csv: intrinsics and camera offsets from the reference camera.\n"
         << "depth/: uint16 PNG, metres x 5000, 0 = no surface.\n"
         << "ids/: uint16 PNG, object id + 1 (0 nothing, 1 room, 1001 the person's arm).\n"
         << "novelty/: uint8 PNG, 255 added object or arm, 128 where a removed object was.\n"
         << "events.csv: the phases and the events as applied.\n"
         << "objects.csv: object id and name.\n";
}

std::string GroundTruthWriter::PhaseOf(int frame) const {
  for (const PhaseSpec& p : scenario_.phases) {
    if (frame >= p.first_frame && frame <= p.last_frame) return p.name;
  }
  return "";
}

void GroundTruthWriter::WriteFrame(int frame, double t, const Eigen::Isometry3d& T,
                                   const Pioneer3dx* robot, const cv::Mat& depth,
                                   const cv::Mat& ids, const cv::Mat& novelty) {
  const Eigen::Quaterniond q(T.linear());
  const Eigen::Vector3d p = T.translation();
  poses_ << frame << "," << t << "," << PhaseOf(frame) << "," << p.x() << "," << p.y() << ","
         << p.z() << "," << q.x() << "," << q.y() << "," << q.z() << "," << q.w();
  if (robot) {
    const Eigen::Vector3d r = robot->TruePose2D();
    const Odometry& o = robot->odometry();
    poses_ << "," << r.x() << "," << r.y() << "," << r.z() << "," << o.x << "," << o.y << ","
           << o.phi << "\n";
  } else {
    poses_ << ",,,,,,\n";
  }
  cv::Mat depth16, ids16;
  depth.convertTo(depth16, CV_16U, ground_truth::kDepthUnitsPerMetre);  // saturates at 13.1 m
  ids.convertTo(ids16, CV_16U, 1.0, ground_truth::kIdOffset);
  const std::string name = core::FrameStem(frame) + ".png";
  core::WriteImage(dir_ + "/depth/" + name, depth16);
  core::WriteImage(dir_ + "/ids/" + name, ids16);
  core::WriteImage(dir_ + "/novelty/" + name, novelty);
}

void GroundTruthWriter::WriteEvents(const std::vector<std::string>& applied) {
  std::ofstream out(dir_ + "/events.csv");
  out << "kind,name,first_frame,last_frame,time,description\n";
  for (const PhaseSpec& p : scenario_.phases) {
    out << "phase," << p.name << "," << p.first_frame << "," << p.last_frame << ",,\""
        << p.description << "\"\n";
  }
  for (const std::string& e : applied) {  // "time kind target"
    std::istringstream in(e);
    double time;
    std::string kind, target;
    in >> time >> kind >> target;
    const int frame = int(time * scenario_.fps) + 1;
    out << "event," << target << "," << frame << "," << frame << "," << time << "," << kind << "\n";
  }
  if (!out) throw std::runtime_error(dir_ + "/events.csv: write failed");
}

void GroundTruthWriter::WriteObjects() {
  std::ofstream out(dir_ + "/objects.csv");
  out << "id,name\n0,room\n";
  for (const ObjectSpec& o : scenario_.objects) out << o.id << "," << o.name << "\n";
  out << ground_truth::kArmId << ",arm\n";
  if (!out) throw std::runtime_error(dir_ + "/objects.csv: write failed");
}

cv::Mat GroundTruthWriter::NoveltyMask(const cv::Mat& ids, const cv::Mat& reference_ids,
                                       const std::vector<int>& added,
                                       const std::vector<int>& removed) {
  cv::Mat mask(ids.size(), CV_8UC1, cv::Scalar(0));
  auto contains = [](const std::vector<int>& v, int id) {
    return std::find(v.begin(), v.end(), id) != v.end();
  };
  for (int i = 0; i < ids.rows * ids.cols; ++i) {
    const int now = ids.at<int>(i), before = reference_ids.at<int>(i);
    if (contains(added, now)) {
      mask.at<uint8_t>(i) = ground_truth::kNoveltyAdded;
    } else if (contains(removed, before) && now != before) {
      mask.at<uint8_t>(i) = ground_truth::kNoveltyRemoved;
    }
  }
  return mask;
}

}  // namespace novelty::sim
