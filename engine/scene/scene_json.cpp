#include "scene/scene_json.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/constants.hpp"

namespace lc {

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  return fmt::format("{:.12g}", v);
}

std::string json_position(const Vec4& p, bool polar) {
  const auto num = json_number;
  if (polar)
    return fmt::format("{{\"t\": {}, \"r\": {}, \"theta\": {}, \"phi\": {}}}", num(p[0]), num(p[1]), num(p[2] / degree),
                       num(p[3] / degree));
  return fmt::format("{{\"t\": {}, \"x\": {}, \"y\": {}, \"z\": {}}}", num(p[0]), num(p[1]), num(p[2]), num(p[3]));
}

std::string json_components(const Vec4& v) {
  return fmt::format("[{}, {}, {}, {}]", json_number(v[0]), json_number(v[1]), json_number(v[2]), json_number(v[3]));
}

namespace {

const auto num = json_number;
const auto position = json_position;

std::string color(const Color& c) { return fmt::format("[{}, {}, {}]", num(c[0]), num(c[1]), num(c[2])); }

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", c);
      continue;
    }
    out += c;
  }
  return out + "\"";
}

// {"kind": name, <each declared parameter>: value}.
std::string spacetime(const Spacetime& st) {
  return std::visit(
      [](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        const typename S::Params p = s.params();
        std::string out = fmt::format("{{\"kind\": \"{}\"", S::name);
        for_each_field<typename S::Params>([&](const auto& f) { out += fmt::format(", \"{}\": {}", f.name, num(p.*(f.member))); });
        return out + "}";
      },
      st);
}

std::string worldline(const WorldlineSpec& w) {
  const bool polar = has_polar_scene(w.spacetime);
  return fmt::format("{{\"spacetime\": {}, \"start\": {}, \"velocity\": [{}, {}, {}], \"duration\": {}, \"where\": {}}}",
                     spacetime(w.spacetime), position(w.start, polar), num(w.velocity[0]), num(w.velocity[1]),
                     num(w.velocity[2]), num(w.duration), quoted(w.where));
}

}  // namespace

std::string to_json(const FrameScene& fs, int frame, const std::string& evaluated) {
  const bool polar = has_polar_scene(fs.spacetime);
  std::string out = fmt::format("{{\"frame\": {}, \"spacetime\": {}, ", frame, spacetime(fs.spacetime));
  const ObserverSpec& o = fs.observer;
  if (o.kind == ObserverKind::free_fall)
    out += fmt::format("\"observer\": {{\"kind\": \"free_fall\", \"proper_time\": {}, \"worldline\": {}}}, ",
                       num(o.proper_time), worldline(*o.worldline));
  else
    out += fmt::format("\"observer\": {{\"kind\": \"{}\", \"position\": {}}}, ",
                       o.kind == ObserverKind::zamo ? "zamo" : "static", position(o.position, polar));
  out += "\"camera\": " + CameraRegistry::json(fs.camera) + ", ";
  if (fs.disk)
    out += fmt::format(
        "\"disk\": {{\"inner\": {}, \"outer\": {}, \"rings\": {}, \"sectors\": {}, \"colors\": [{}, {}]}}, ",
        num(fs.disk->inner), num(fs.disk->outer), fs.disk->rings, fs.disk->sectors, color(fs.disk->color_a),
        color(fs.disk->color_b));
  else
    out += "\"disk\": null, ";
  out += "\"sky\": " + SkyRegistry::json(fs.sky) + ", ";
  out += "\"objects\": [";
  for (std::size_t i = 0; i < fs.spheres.size(); ++i) {
    const SphereSpec& s = fs.spheres[i];
    out += i ? ", " : "";
    out += fmt::format("{{\"kind\": \"sphere\", \"radius\": {}, ", num(s.radius));
    if (s.position)
      out += fmt::format("\"position\": {}", position(*s.position, polar));
    else
      out += fmt::format("\"worldline\": {}", worldline(*s.worldline));
    out += "}";
  }
  out += "]";
  if (!evaluated.empty()) out += ", \"evaluated\": " + evaluated;
  return out + "}";
}

}  // namespace lc
