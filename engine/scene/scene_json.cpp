#include "scene/scene_json.hpp"

#include <fmt/format.h>

#include "scene/scene_skies.hpp"

namespace lc {

// Every part as its registry or declaration writes it; positions in the
// scene's chart, angles in degrees.
std::string to_json(const SceneSpec& fs, int frame, const std::string& evaluated) {
  const bool polar = has_polar_scene(fs.spacetime);
  std::string out = fmt::format("{{\"frame\": {}, \"spacetime\": {}, ", frame, spacetime_json(fs.spacetime));
  out += "\"observer\": " + ObserverRegistry::json(fs.observer, polar) + ", ";
  out += "\"camera\": " + kind_json(fs.camera) + ", ";
  // The scene's sky, then (where a further end has its own) "skies" by end
  // name, as the shot writes them.
  std::string skies;
  for_each_sky(fs, [&](std::string_view end, const SkySpec& sky) {
    if (end.empty())
      out += "\"sky\": " + SkyRegistry::json(sky) + ", ";
    else
      skies += fmt::format("{}\"{}\": {}", skies.empty() ? "" : ", ", end, SkyRegistry::json(sky));
  });
  if (!skies.empty()) out += "\"skies\": {" + skies + "}, ";
  out += "\"objects\": [";
  for (std::size_t i = 0; i < fs.objects.size(); ++i) out += (i ? ", " : "") + kind_json(fs.objects[i], polar);
  out += "]";
  out += fmt::format(", \"light\": {{{}}}", fields_json(fs.light).substr(2));
  if (!evaluated.empty()) out += ", \"evaluated\": " + evaluated;
  return out + "}";
}

}  // namespace lc
