#include "sim/scenario/scenario_parser.h"
#include "core/rigid_pose.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <functional>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace novelty::sim {

const ObjectSpec* Scenario::FindObject(const std::string& n) const {
  for (const ObjectSpec& o : objects) {
    if (o.name == n) return &o;
  }
  return nullptr;
}

namespace {

constexpr double kDeg = M_PI / 180.0;

// The ranges every number is checked against (scenario_parser.h lists them): beyond them ODE and
// Embree assert, buffers take gigabytes, or a run never ends.
struct Range {
  double lo, hi;
};
constexpr Range kPlace{-1000, 1000};   // positions, m
constexpr Range kAngle{-3600, 3600};   // degrees
constexpr Range kColour{0, 1e4};       // colours and lamp intensities
constexpr Range kImageSide{8, 4096};   // camera width and height, pixels
constexpr Range kCount{1, 1000000};    // frames, phase frames
constexpr double kMaxSize = 100;       // object, room and window sizes, m
constexpr double kMaxSeconds = 86400;  // times and durations

std::string Str(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

// A name that is also a file name in --out: no folders, no hidden files.
bool PlainName(const std::string& n) {
  if (n.empty() || n.size() > 100 || n[0] == '.') return false;
  for (const char c : n)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.')
      return false;
  return true;
}

// The tokens of one line and a cursor, with errors that name file and line.
class Line {
 public:
  Line(std::vector<std::string> tokens, std::string where)
      : tokens_(std::move(tokens)), where_(std::move(where)) {}

  [[noreturn]] void Fail(const std::string& problem) const {
    throw std::runtime_error(where_ + ": " + problem);
  }
  bool Done() const { return pos_ >= tokens_.size(); }
  const std::string& Keyword() const { return tokens_[0]; }
  std::string Word(const char* what) {
    if (Done()) Fail(std::string("missing ") + what + " after '" + tokens_[pos_ - 1] + "'");
    return tokens_[pos_++];
  }
  double Number(const char* what) {
    const std::string t = Word(what);
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    if (end == t.c_str() || *end != '\0' || !std::isfinite(v)) {
      Fail(std::string("expected a number for ") + what + ", got '" + t + "'");
    }
    return v;
  }
  /// A number in [lo, hi]: what the simulator (ODE, Embree, the frame buffers) can take.
  double In(const char* what, Range r) {
    const double v = Number(what);
    if (!(v >= r.lo && v <= r.hi)) {
      Fail(std::string(what) + " must be in [" + Str(r.lo) + ", " + Str(r.hi) + "], got " + Str(v));
    }
    return v;
  }
  /// A number in (0, hi].
  double Positive(const char* what, double hi) {
    const double v = Number(what);
    if (!(v > 0 && v <= hi))
      Fail(std::string(what) + " must be in (0, " + Str(hi) + "], got " + Str(v));
    return v;
  }
  int Integer(const char* what, Range r) {
    const double v = In(what, r);
    if (v != std::floor(v)) Fail(std::string(what) + " must be an integer");
    return static_cast<int>(v);
  }
  Eigen::Vector3f Colour(const char* what) {
    Eigen::Vector3f c;
    for (int k = 0; k < 3; ++k) c[k] = static_cast<float>(In(what, kColour));
    return c;
  }
  Eigen::Vector3d Vec3(const char* what, Range r = kPlace) {
    const double x = In(what, r), y = In(what, r), z = In(what, r);
    return {x, y, z};
  }
  bool Accept(const std::string& word) {
    if (!Done() && tokens_[pos_] == word) {
      ++pos_;
      return true;
    }
    return false;
  }
  std::string Rest() {
    std::string s;
    while (!Done()) s += (s.empty() ? "" : " ") + tokens_[pos_++];
    return s;
  }
  void ExpectEnd() const {
    if (!Done()) Fail("unexpected '" + tokens_[pos_] + "'");
  }
  int number() const { return line_number_; }
  void set_number(int n) { line_number_ = n; }

 private:
  std::vector<std::string> tokens_;
  std::string where_;
  std::size_t pos_ = 1;
  int line_number_ = 0;
};

class Parser {
 public:
  Parser(std::string file, std::string base_dir) : base_dir_(std::move(base_dir)) {
    s_.file = std::move(file);
    s_.lighting.points.clear();
  }

  void Statement(Line& l) {
    const std::string& k = l.Keyword();
    if (k == "name")
      Name(l);
    else if (k == "frames")
      s_.frames = l.Integer("frames", kCount);
    else if (k == "fps")
      s_.fps = l.In("fps", {0.1, 1000});
    else if (k == "seed")
      s_.seed = static_cast<std::uint64_t>(l.Integer("seed", {0, 2147483647}));
    else if (k == "camera")
      Camera(l);
    else if (k == "rig")
      Rig(l);
    else if (k == "sensor")
      Sensor(l);
    else if (k == "mount")
      Mount(l);
    else if (k == "static_camera")
      StaticCamera(l);
    else if (k == "room")
      s_.room = {l.Positive("room x", kMaxSize), l.Positive("room y", kMaxSize),
                 l.Positive("height", kMaxSize)};
    else if (k == "window")
      Window(l);
    else if (k == "ambient")
      s_.lighting.ambient = l.Colour("ambient colour");
    else if (k == "sky")
      s_.render.background = l.Colour("sky colour");
    else if (k == "daylight")
      Daylight(l);
    else if (k == "material")
      MaterialStatement(l);
    else if (k == "texture")
      TextureStatement(l);
    else if (k == "object")
      Object(l);
    else if (k == "lamp")
      Lamp(l);
    else if (k == "arc")
      Arc(l);
    else if (k == "stop")
      s_.trajectory.AddStop(l.In("stop seconds", {0, kMaxSeconds}));
    else if (k == "repeat")
      Repeat(l);
    else if (k == "start_offset")
      s_.start_offset = {l.In("dx", {-10, 10}), l.In("dy", {-10, 10})};
    else if (k == "event")
      Event(l);
    else if (k == "phase")
      Phase(l);
    else
      l.Fail("unknown keyword '" + k + "'");
    if (k != "phase") l.ExpectEnd();
  }

  Scenario Finish(const std::string& where) {
    if (s_.name.empty()) throw std::runtime_error(where + ": no 'name' statement");
    if (!s_.static_camera && s_.trajectory.empty()) {
      throw std::runtime_error(where + ": neither 'static_camera' nor a trajectory ('arc')");
    }
    // A frame's rays, bounded so that one frame renders in seconds, not hours.
    const double rays = double(s_.camera.width) * s_.camera.height * s_.render.pixel_samples *
                        s_.render.pixel_samples;
    if (rays > double(1 << 26)) {
      throw std::runtime_error(where + ": camera size × pixel_samples² is " + Str(rays) +
                               " rays a frame, over " + Str(1 << 26));
    }
    for (const EventSpec& e : s_.events) {
      if (e.time > s_.Duration()) {
        throw std::runtime_error(where + ":" + std::to_string(e.line) + ": event at " +
                                 std::to_string(e.time) + " s is after the run's end (" +
                                 std::to_string(s_.Duration()) + " s)");
      }
    }
    return std::move(s_);
  }

 private:
  void Name(Line& l) {
    s_.name = l.Word("name");
    if (!PlainName(s_.name))
      l.Fail("name '" + s_.name + "' must be a plain file name (letters, digits, _ - .)");
  }

  void Repeat(Line& l) {
    constexpr int kMaxSegments = 100000;
    const int times = l.Integer("repeat count", {1, kMaxSegments});
    if (double(s_.trajectory.size()) * (times + 1) > kMaxSegments)
      l.Fail("repeat makes more than " + std::to_string(kMaxSegments) + " trajectory segments");
    s_.trajectory.Repeat(times);
  }

  void Camera(Line& l) {
    const int w = l.Integer("width", kImageSide), h = l.Integer("height", kImageSide);
    const double fov = l.In("horizontal field of view", {1, 170});
    s_.camera = core::PinholeCamera::FromFov(w, h, fov * kDeg);
  }

  void Rig(Line& l) {
    const std::string kind = l.Word("rig kind");
    if (kind == "mono")
      s_.rig.kind = RigKind::kMono;
    else if (kind == "rgbd")
      s_.rig.kind = RigKind::kRgbd;
    else if (kind == "stereo")
      s_.rig = {RigKind::kStereo, l.Positive("baseline", 10)};
    else if (kind == "trinocular")
      s_.rig = {RigKind::kTrinocular, l.Positive("baseline", 10)};
    else
      l.Fail("unknown rig '" + kind + "' (mono, rgbd, stereo, trinocular)");
  }

  void Sensor(Line& l) {
    while (!l.Done()) {
      const std::string key = l.Word("sensor setting");
      if (key == "noise")
        s_.render.noise_sigma = l.In("noise", {0, 100});
      else if (key == "gamma")
        s_.render.gamma = l.In("gamma", {0.1, 10});
      else if (key == "exposure")
        s_.render.exposure = l.In("exposure", {1e-4, 1e4});
      else if (key == "shadow_samples")
        s_.render.soft_shadow_samples = l.Integer("shadow_samples", {1, 256});
      else if (key == "pixel_samples")
        s_.render.pixel_samples = l.Integer("pixel_samples", {1, 8});
      else
        l.Fail("unknown sensor setting '" + key +
               "' (noise, gamma, exposure, shadow_samples, pixel_samples)");
    }
  }

  void Mount(Line& l) {
    s_.mount.position = l.Vec3("mount position", {-10, 10});
    s_.mount.yaw = l.In("mount yaw", kAngle) * kDeg;
    s_.mount.pitch = l.In("mount pitch", {-90, 90}) * kDeg;
  }

  void StaticCamera(Line& l) {
    const Eigen::Vector3d eye = l.Vec3("camera position"), target = l.Vec3("target");
    try {
      s_.static_camera = core::LookAt(eye, target);
    } catch (const std::invalid_argument& e) {
      l.Fail(e.what());
    }
  }

  void Window(Line& l) {
    // Braced initialisation: the four values are read left to right (call arguments are not).
    s_.window = Eigen::Vector4d{l.In("window x", kPlace), l.In("window z", kPlace),
                                l.Positive("width", kMaxSize), l.Positive("height", kMaxSize)};
  }

  void Daylight(Line& l) {
    DirectionalLight d;
    d.direction = l.Vec3("daylight direction", {-1e3, 1e3});
    if (d.direction.norm() < 1e-9) l.Fail("daylight direction is zero");
    d.direction.normalize();
    d.irradiance = l.Colour("daylight colour");
    s_.lighting.directional.push_back(d);
  }

  void MaterialStatement(Line& l) {
    const std::string name = l.Word("material name");
    const std::string kind = l.Word("material kind");
    Material m;
    m.diffuse = l.Colour("colour");
    if (kind == "phong") {
      if (!l.Done()) {
        m.specular = float(l.In("ks", {0, 1}));
        m.shininess = float(l.Positive("shininess", 1e4));
      }
    } else if (kind == "metal" || kind == "glass") {
      m.kind = kind == "metal" ? Material::Kind::kMetal : Material::Kind::kGlass;
      m.specular = float(l.In("ks", {0, 1}));
      m.shininess = float(l.Positive("shininess", 1e4));
      if (kind == "metal")
        m.reflectivity = float(l.In("reflectivity", {0, 1}));
      else
        m.ior = float(l.In("index of refraction", {1, 5}));
    } else {
      l.Fail("unknown material kind '" + kind + "' (phong, metal, glass)");
    }
    s_.materials[name] = m;
  }

  void TextureStatement(Line& l) {
    const std::string name = l.Word("material name");
    auto it = s_.materials.find(name);
    if (it == s_.materials.end()) l.Fail("texture for undeclared material '" + name + "'");
    Texture& t = it->second.texture;
    const std::string kind = l.Word("texture kind");
    if (kind == "checker" || kind == "stripes") {
      t.kind = kind == "checker" ? Texture::Kind::kChecker : Texture::Kind::kStripes;
      t.second = l.Colour("second colour");
      t.cells = float(l.Positive("cells", 1e4));
    } else if (kind == "image") {
      const std::string file = base_dir_ + "/" + l.Word("image file");
      cv::Mat bgr = cv::imread(file, cv::IMREAD_COLOR);
      if (bgr.empty()) l.Fail("cannot read texture image '" + file + "'");
      if (bgr.cols > 8192 || bgr.rows > 8192)
        l.Fail("texture image '" + file + "' is over 8192 pixels");
      cv::cvtColor(bgr, t.image, cv::COLOR_BGR2RGB);
      t.kind = Texture::Kind::kImage;
    } else {
      l.Fail("unknown texture '" + kind + "' (checker, stripes, image)");
    }
  }

  void Object(Line& l) {
    ObjectSpec o;
    o.line = l.number();
    o.name = l.Word("object name");
    if (s_.FindObject(o.name)) l.Fail("object '" + o.name + "' declared twice");
    o.id = static_cast<int>(s_.objects.size()) + 1;
    const std::string shape = l.Word("shape");
    // Sizes from 1 mm: below, ODE's contacts and Embree's triangles degenerate.
    const Range size{1e-3, kMaxSize};
    if (shape == "box")
      o.shape = Shape::kBox, o.dims = l.Vec3("box size", size);
    else if (shape == "cylinder")
      o.shape = Shape::kCylinder, o.dims = {l.In("radius", size), l.In("height", size), 0};
    else if (shape == "cup")
      o.shape = Shape::kCup, o.dims = {l.In("radius", size), l.In("height", size), 0};
    else if (shape == "sphere")
      o.shape = Shape::kSphere, o.dims = {l.In("radius", size), 0, 0};
    else if (shape == "plate")
      o.shape = Shape::kPlate, o.dims = {l.In("radius", size), 0, 0};
    else if (shape == "plane")
      o.shape = Shape::kPlane, o.dims = {l.In("size x", size), l.In("size y", size), 0};
    else
      l.Fail("unknown shape '" + shape + "' (box, cylinder, sphere, cup, plate, plane)");
    o.material = l.Word("material");
    if (!s_.materials.count(o.material)) l.Fail("undeclared material '" + o.material + "'");
    if (!l.Accept("at")) l.Fail("expected 'at X Y' after the material");
    o.xy = {l.In("x", {-kMaxSize, kMaxSize}), l.In("y", {-kMaxSize, kMaxSize})};
    o.support = "floor";
    while (!l.Done()) {
      if (l.Accept("yaw"))
        o.yaw = l.In("yaw", kAngle) * kDeg;
      else if (l.Accept("on"))
        o.support = l.Word("support");
      else if (l.Accept("fixed"))
        o.fixed = true;
      else if (l.Accept("absent"))
        o.present = false;
      else if (l.Accept("mass"))
        o.mass = l.In("mass", {1e-3, 1e4});
      else
        l.Fail("unexpected '" + l.Word("option") + "' (yaw, on, fixed, absent, mass)");
    }
    if (o.support != "floor" && !s_.FindObject(o.support)) {
      l.Fail("support '" + o.support + "' is not a declared object");
    }
    s_.objects.push_back(o);
  }

  void Lamp(Line& l) {
    LampSpec lamp;
    lamp.name = l.Word("lamp name");
    lamp.light.position = l.Vec3("lamp position");
    lamp.light.intensity = l.Colour("lamp intensity");
    while (!l.Done()) {
      if (l.Accept("radius"))
        lamp.light.radius = l.In("radius", {0, 10});
      else if (l.Accept("off"))
        lamp.on = false;
      else
        l.Fail("unexpected '" + l.Word("option") + "' (radius, off)");
    }
    s_.lamps.push_back(lamp);
  }

  void Arc(Line& l) {
    const Eigen::Vector2d c{l.In("centre x", {-kMaxSize, kMaxSize}),
                            l.In("centre y", {-kMaxSize, kMaxSize})};
    const double r = l.In("radius", {1e-2, kMaxSize}), from = l.In("from", kAngle) * kDeg,
                 to = l.In("to", kAngle) * kDeg;
    const double speed = l.In("speed", {1e-3, 10});
    if (from == to) l.Fail("arc from and to angles are equal");
    s_.trajectory.AddArc(c, r, from, to, speed);
  }

  void Event(Line& l) {
    EventSpec e;
    e.line = l.number();
    e.time = l.In("event time", {0, kMaxSeconds});
    const std::string kind = l.Word("event kind");
    if (kind == "sun") {
      if (s_.lighting.directional.empty())
        l.Fail("a sun event needs 'daylight' declared before it");
      e.kind = EventSpec::Kind::kSun;
      e.position = l.Vec3("sun direction", {-1e3, 1e3});
      if (!(e.position.norm() > 1e-6)) l.Fail("sun direction must not be zero");
      e.position.normalize();
      if (l.Accept("over")) e.duration = l.Positive("over seconds", kMaxSeconds);
      s_.events.push_back(e);
      return;
    }
    if (kind == "exposure") {
      e.kind = EventSpec::Kind::kExposure;
      e.value = l.In("exposure", {1e-4, 1e4});
      if (l.Accept("over")) e.duration = l.Positive("over seconds", kMaxSeconds);
      s_.events.push_back(e);
      return;
    }
    e.target = l.Word("event target");
    if (kind == "add" || kind == "remove" || kind == "move" || kind == "walk") {
      e.kind = kind == "add"      ? EventSpec::Kind::kAdd
               : kind == "remove" ? EventSpec::Kind::kRemove
               : kind == "move"   ? EventSpec::Kind::kMove
                                  : EventSpec::Kind::kWalk;
      const ObjectSpec* o = s_.FindObject(e.target);
      if (!o) l.Fail("event on undeclared object '" + e.target + "'");
      if (o->fixed) l.Fail("object '" + e.target + "' is fixed furniture and cannot change");
      if (e.kind == EventSpec::Kind::kMove || e.kind == EventSpec::Kind::kWalk)
        e.position = {l.In("x", {-kMaxSize, kMaxSize}), l.In("y", {-kMaxSize, kMaxSize}), 0};
      if (e.kind == EventSpec::Kind::kWalk)
        e.duration = l.Positive("walk seconds", kMaxSeconds);
      else if (l.Accept("arm"))
        e.arm_duration = l.Positive("arm seconds", 600);
    } else if (kind == "lamp" || kind == "lamp_on" || kind == "lamp_off") {
      e.kind = kind == "lamp"      ? EventSpec::Kind::kLampMove
               : kind == "lamp_on" ? EventSpec::Kind::kLampOn
                                   : EventSpec::Kind::kLampOff;
      bool found = false;
      for (const LampSpec& lamp : s_.lamps) found |= lamp.name == e.target;
      if (!found) l.Fail("event on undeclared lamp '" + e.target + "'");
      if (e.kind == EventSpec::Kind::kLampMove) e.position = l.Vec3("lamp position");
    } else {
      l.Fail("unknown event '" + kind +
             "' (add, remove, move, walk, lamp, lamp_on, lamp_off, sun, exposure)");
    }
    s_.events.push_back(e);
  }

  void Phase(Line& l) {
    PhaseSpec p;
    p.name = l.Word("phase name");
    p.first_frame = l.Integer("first frame", kCount);
    p.last_frame = l.Integer("last frame", kCount);
    if (p.last_frame < p.first_frame) l.Fail("phase ends before it starts");
    p.description = l.Rest();
    s_.phases.push_back(p);
  }

  Scenario s_;
  std::string base_dir_;
};

std::vector<std::string> Tokens(const std::string& text) {
  std::istringstream in(text.substr(0, text.find('#')));
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

}  // namespace

Scenario ParseScenario(std::istream& in, const std::string& name_for_errors,
                       const std::string& base_dir) {
  Parser parser(name_for_errors, base_dir);
  std::string text;
  int number = 0;
  while (std::getline(in, text)) {
    ++number;
    std::vector<std::string> tokens = Tokens(text);
    if (tokens.empty()) continue;
    Line line(std::move(tokens), name_for_errors + ":" + std::to_string(number));
    line.set_number(number);
    try {
      parser.Statement(line);
    } catch (const std::invalid_argument& e) {  // from Trajectory and friends
      line.Fail(e.what());
    }
  }
  return parser.Finish(name_for_errors);
}

Scenario LoadScenario(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open scenario file");
  const std::size_t slash = path.find_last_of('/');
  return ParseScenario(in, path, slash == std::string::npos ? "." : path.substr(0, slash));
}

}  // namespace novelty::sim
