#include "sim/scenario/scenario_parser.h"
#include "core/rigid_pose.h"

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
  double Positive(const char* what) {
    const double v = Number(what);
    if (!(v > 0)) Fail(std::string(what) + " must be > 0, got " + std::to_string(v));
    return v;
  }
  int Integer(const char* what) {
    const double v = Number(what);
    if (v != std::floor(v)) Fail(std::string(what) + " must be an integer");
    return static_cast<int>(v);
  }
  Eigen::Vector3f Colour(const char* what) {
    Eigen::Vector3f c;
    for (int k = 0; k < 3; ++k) {
      c[k] = static_cast<float>(Number(what));
      if (c[k] < 0) Fail(std::string(what) + " components must be >= 0");
    }
    return c;
  }
  Eigen::Vector3d Vec3(const char* what) {
    const double x = Number(what), y = Number(what), z = Number(what);
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
      s_.name = l.Word("name");
    else if (k == "frames")
      s_.frames = PositiveInt(l, "frames");
    else if (k == "fps")
      s_.fps = l.Positive("fps");
    else if (k == "seed")
      s_.seed = static_cast<std::uint64_t>(l.Integer("seed"));
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
      s_.room = {l.Positive("room x"), l.Positive("room y"), l.Positive("height")};
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
      s_.trajectory.AddStop(l.Number("stop seconds"));
    else if (k == "repeat")
      s_.trajectory.Repeat(PositiveInt(l, "repeat count"));
    else if (k == "start_offset")
      s_.start_offset = {l.Number("dx"), l.Number("dy")};
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
  static int PositiveInt(Line& l, const char* what) {
    const int v = l.Integer(what);
    if (v <= 0) l.Fail(std::string(what) + " must be > 0");
    return v;
  }

  void Camera(Line& l) {
    const int w = PositiveInt(l, "width"), h = PositiveInt(l, "height");
    const double fov = l.Positive("horizontal field of view");
    if (fov >= 179) l.Fail("field of view must be < 179 degrees");
    s_.camera = core::PinholeCamera::FromFov(w, h, fov * kDeg);
  }

  void Rig(Line& l) {
    const std::string kind = l.Word("rig kind");
    if (kind == "mono")
      s_.rig.kind = RigKind::kMono;
    else if (kind == "rgbd")
      s_.rig.kind = RigKind::kRgbd;
    else if (kind == "stereo")
      s_.rig = {RigKind::kStereo, l.Positive("baseline")};
    else if (kind == "trinocular")
      s_.rig = {RigKind::kTrinocular, l.Positive("baseline")};
    else
      l.Fail("unknown rig '" + kind + "' (mono, rgbd, stereo, trinocular)");
  }

  void Sensor(Line& l) {
    while (!l.Done()) {
      const std::string key = l.Word("sensor setting");
      if (key == "noise")
        s_.render.noise_sigma = l.Number("noise");
      else if (key == "gamma")
        s_.render.gamma = l.Positive("gamma");
      else if (key == "exposure")
        s_.render.exposure = l.Positive("exposure");
      else if (key == "shadow_samples")
        s_.render.soft_shadow_samples = PositiveInt(l, "shadow_samples");
      else if (key == "pixel_samples")
        s_.render.pixel_samples = PositiveInt(l, "pixel_samples");
      else
        l.Fail("unknown sensor setting '" + key +
               "' (noise, gamma, exposure, shadow_samples, pixel_samples)");
    }
  }

  void Mount(Line& l) {
    s_.mount.position = l.Vec3("mount position");
    s_.mount.yaw = l.Number("mount yaw") * kDeg;
    s_.mount.pitch = l.Number("mount pitch") * kDeg;
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
    s_.window = Eigen::Vector4d{l.Number("window x"), l.Number("window z"), l.Positive("width"),
                                l.Positive("height")};
  }

  void Daylight(Line& l) {
    DirectionalLight d;
    d.direction = l.Vec3("daylight direction");
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
        m.specular = float(l.Number("ks"));
        m.shininess = float(l.Positive("shininess"));
      }
    } else if (kind == "metal" || kind == "glass") {
      m.kind = kind == "metal" ? Material::Kind::kMetal : Material::Kind::kGlass;
      m.specular = float(l.Number("ks"));
      m.shininess = float(l.Positive("shininess"));
      if (kind == "metal")
        m.reflectivity = float(l.Number("reflectivity"));
      else
        m.ior = float(l.Positive("index of refraction"));
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
      t.cells = float(l.Positive("cells"));
    } else if (kind == "image") {
      const std::string file = base_dir_ + "/" + l.Word("image file");
      cv::Mat bgr = cv::imread(file, cv::IMREAD_COLOR);
      if (bgr.empty()) l.Fail("cannot read texture image '" + file + "'");
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
    if (shape == "box")
      o.shape = Shape::kBox, o.dims = l.Vec3("box size");
    else if (shape == "cylinder")
      o.shape = Shape::kCylinder, o.dims = {l.Positive("radius"), l.Positive("height"), 0};
    else if (shape == "cup")
      o.shape = Shape::kCup, o.dims = {l.Positive("radius"), l.Positive("height"), 0};
    else if (shape == "sphere")
      o.shape = Shape::kSphere, o.dims = {l.Positive("radius"), 0, 0};
    else if (shape == "plate")
      o.shape = Shape::kPlate, o.dims = {l.Positive("radius"), 0, 0};
    else if (shape == "plane")
      o.shape = Shape::kPlane, o.dims = {l.Positive("size x"), l.Positive("size y"), 0};
    else
      l.Fail("unknown shape '" + shape + "' (box, cylinder, sphere, cup, plate, plane)");
    if (o.shape == Shape::kBox && (o.dims.array() <= 0).any()) l.Fail("box sizes must be > 0");
    o.material = l.Word("material");
    if (!s_.materials.count(o.material)) l.Fail("undeclared material '" + o.material + "'");
    if (!l.Accept("at")) l.Fail("expected 'at X Y' after the material");
    o.xy = {l.Number("x"), l.Number("y")};
    o.support = "floor";
    while (!l.Done()) {
      if (l.Accept("yaw"))
        o.yaw = l.Number("yaw") * kDeg;
      else if (l.Accept("on"))
        o.support = l.Word("support");
      else if (l.Accept("fixed"))
        o.fixed = true;
      else if (l.Accept("absent"))
        o.present = false;
      else if (l.Accept("mass"))
        o.mass = l.Positive("mass");
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
        lamp.light.radius = l.Number("radius");
      else if (l.Accept("off"))
        lamp.on = false;
      else
        l.Fail("unexpected '" + l.Word("option") + "' (radius, off)");
    }
    s_.lamps.push_back(lamp);
  }

  void Arc(Line& l) {
    const Eigen::Vector2d c{l.Number("centre x"), l.Number("centre y")};
    const double r = l.Positive("radius"), from = l.Number("from") * kDeg,
                 to = l.Number("to") * kDeg;
    const double speed = l.Positive("speed");
    if (from == to) l.Fail("arc from and to angles are equal");
    s_.trajectory.AddArc(c, r, from, to, speed);
  }

  void Event(Line& l) {
    EventSpec e;
    e.line = l.number();
    e.time = l.Number("event time");
    if (e.time < 0) l.Fail("event time must be >= 0");
    const std::string kind = l.Word("event kind");
    e.target = l.Word("event target");
    if (kind == "add" || kind == "remove" || kind == "move") {
      e.kind = kind == "add"      ? EventSpec::Kind::kAdd
               : kind == "remove" ? EventSpec::Kind::kRemove
                                  : EventSpec::Kind::kMove;
      const ObjectSpec* o = s_.FindObject(e.target);
      if (!o) l.Fail("event on undeclared object '" + e.target + "'");
      if (o->fixed) l.Fail("object '" + e.target + "' is fixed furniture and cannot change");
      if (e.kind == EventSpec::Kind::kMove) e.position = {l.Number("x"), l.Number("y"), 0};
      if (l.Accept("arm")) e.arm_duration = l.Positive("arm seconds");
    } else if (kind == "lamp" || kind == "lamp_on" || kind == "lamp_off") {
      e.kind = kind == "lamp"      ? EventSpec::Kind::kLampMove
               : kind == "lamp_on" ? EventSpec::Kind::kLampOn
                                   : EventSpec::Kind::kLampOff;
      bool found = false;
      for (const LampSpec& lamp : s_.lamps) found |= lamp.name == e.target;
      if (!found) l.Fail("event on undeclared lamp '" + e.target + "'");
      if (e.kind == EventSpec::Kind::kLampMove) e.position = l.Vec3("lamp position");
    } else {
      l.Fail("unknown event '" + kind + "' (add, remove, move, lamp, lamp_on, lamp_off)");
    }
    s_.events.push_back(e);
  }

  void Phase(Line& l) {
    PhaseSpec p;
    p.name = l.Word("phase name");
    p.first_frame = PositiveInt(l, "first frame");
    p.last_frame = PositiveInt(l, "last frame");
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
