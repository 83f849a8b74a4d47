#include "script/constructor_docs.hpp"

#include <type_traits>

#include <fmt/format.h>

#include "camera/camera_params.hpp"
#include "core/fields.hpp"
#include "light/light.hpp"
#include "objects/objects.hpp"
#include "observers/observers.hpp"
#include "scene/shot_info.hpp"
#include "sky/sky.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

namespace {

// A default as a shot author would write it.
template <class T>
std::string default_text(const T& v) {
  if constexpr (std::is_same_v<T, Palette>)
    return fmt::format("{{{{{:g}, {:g}, {:g}}}, {{{:g}, {:g}, {:g}}}}}", v.a[0], v.a[1], v.a[2], v.b[0], v.b[1], v.b[2]);
  else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, std::string_view>)
    return fmt::format("\"{}\"", v);
  else if constexpr (Choice<T>)
    return fmt::format("\"{}\"", choice_name(v));
  else if constexpr (std::is_same_v<T, HoleList>)
    return people_text(v);
  else
    return fmt::format("{:g}", static_cast<double>(v));
}

// Text for a Markdown table cell: '|' would end the cell.
std::string cell(std::string_view s) {
  std::string out;
  for (char c : s) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

// "#### lc.name{...}" and a table of the fields of P (and what P reads
// besides them, if it says: extra_doc; where that is all, it alone).
template <class P>
std::string table(std::string_view name, std::string_view heading = {}) {
  std::string out = heading.empty() ? fmt::format("#### `lc.{}{{...}}`\n\n", name) : fmt::format("{}:\n\n", heading);
  bool any = false;
  for_each_field<P>([&](const auto&) { any = true; });
  if (!any && !requires { P::extra_doc; }) out += "No fields.\n\n";
  if (any) out += "| field | default | range | meaning |\n| --- | --- | --- | --- |\n";
  for_each_field<P>([&](const auto& f) {
    using T = typename std::decay_t<decltype(f)>::Value;
    const std::string unit = f.unit.empty() ? std::string() : fmt::format(" {}", f.unit);
    std::string fallback = "required", name = fmt::format("`{}`", f.name);
    if constexpr (KeyedByValue<T>) {
      // Its keys, not its label: the shot writes one of them.
      name.clear();
      for (std::size_t i = 0; i < T::field_names.size(); ++i)
        name += fmt::format("{}`{}`", i == 0 ? "" : i + 1 == T::field_names.size() ? " or " : ", ", T::field_names[i]);
    } else if (f.fallback) {
      fallback = default_text(*f.fallback) + unit;
    }
    std::string range = range_text(f.lo, f.hi);
    if constexpr (Choice<T>) range = choices_text<T>();
    else if constexpr (std::is_integral_v<T>) range = integer_range_text(f.lo, f.hi);
    out += fmt::format("| {} | {} | {} | {} |\n", name, cell(fallback), range.empty() ? "" : range + unit,
                       cell(f.doc));
  });
  if (any) out += "\n";
  if constexpr (requires { P::extra_doc; }) out += fmt::format("{}\n\n", P::extra_doc);
  return out;
}

}  // namespace

std::string constructor_tables() {
  std::string out = "### The shot table\n\n";
  out += table<ShotInfo>("", "The table a shot returns, besides its `frame` function");
  out += "### Spacetimes\n\n";
  SpacetimeRegistry::for_each([&](auto* kind) {
    using S = std::remove_pointer_t<decltype(kind)>;
    out += table<typename S::Params>(S::name);
  });
  auto kinds = [&](const char* heading, auto registry) {
    out += fmt::format("### {}\n\n", heading);
    decltype(registry)::for_each([&](auto* kind) {
      using K = std::remove_pointer_t<decltype(kind)>;
      out += table<typename K::Params>(K::name);
    });
  };
  kinds("Observers", ObserverRegistry{});
  kinds("Cameras", CameraSpecs{});
  kinds("Skies", SkyRegistry{});
  kinds("Objects", ObjectSpecs{});
  out += "### Light\n\n";
  out += table<LightParams>("light");
  return out;
}

}  // namespace lc
