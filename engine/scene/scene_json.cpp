#include "scene/scene_json.hpp"

#include <fmt/format.h>

namespace lc {

// Every part as its registry or declaration writes it; positions in the
// scene's chart, angles in degrees.
std::string to_json(const SceneSpec& fs, int frame, const std::string& evaluated) {
  const bool polar = has_polar_scene(fs.spacetime);
  std::string out = fmt::format("{{\"frame\": {}, \"spacetime\": {}, ", frame, spacetime_json(fs.spacetime));
  out += "\"observer\": " + ObserverRegistry::json(fs.observer, polar) + ", ";
  out += "\"camera\": " + kind_json(fs.camera) + ", ";
  out += "\"sky\": " + SkyRegistry::json(fs.sky) + ", ";
  out += "\"objects\": [";
  for (std::size_t i = 0; i < fs.objects.size(); ++i) out += (i ? ", " : "") + kind_json(fs.objects[i], polar);
  out += "]";
  out += fmt::format(", \"light\": {{{}}}", fields_json(fs.light).substr(2));
  if (!evaluated.empty()) out += ", \"evaluated\": " + evaluated;
  return out + "}";
}

}  // namespace lc
