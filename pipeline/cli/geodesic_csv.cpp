#include "geodesic_csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/line_reader.hpp"

namespace lc {

std::string geodesic_csv_header(const std::vector<Spacetime>& spacetimes, bool with_tetrad, bool bundle) {
  std::string names;
  for (const Spacetime& st : spacetimes) {
    const std::string name(spacetime_name(st));
    if ((", " + names + ", ").find(", " + name + ", ") == std::string::npos)
      names += fmt::format("{}{}", names.empty() ? "" : ", ", name);
  }
  const SceneChart chart = spacetimes.empty() ? SceneChart::polar : scene_chart(spacetimes.front());
  std::string out = fmt::format("# chart: {} ({}; {})\n", csv_chart_name(chart),
                                chart == SceneChart::polar ? "t, r, theta, phi" : "t, x, y, z", names);
  out += bundle ? "ray,lambda,x0,x1,x2,x3,u0,u1,u2,u3" : "lambda,x0,x1,x2,x3,u0,u1,u2,u3";
  if (with_tetrad)
    for (int a = 0; a < 4; ++a)
      for (int m = 0; m < 4; ++m) out += fmt::format(",e{}{}", a, m);
  out += '\n';
  return out;
}

void append_geodesic_csv(std::string& out, const Spacetime& spacetime, const GeodesicPath& path, bool with_tetrad,
                         std::optional<int> ray) {
  const bool polar = has_polar_scene(spacetime);
  double phi_prev = 0.0, phi_offset = 0.0;
  bool first = true;
  for (const auto& s : path.samples) {
    Vec4 x = scene_from_trace(spacetime, s.x);
    if (polar) {
      // Unwrap phi: choose the 2 pi branch nearest the previous sample.
      if (!first) phi_offset += two_pi * std::round((phi_prev - (x[3] + phi_offset)) / two_pi);
      phi_prev = x[3] + phi_offset;
      x[3] = phi_prev;
      first = false;
    }
    const Vec4 u = scene_vector(spacetime, s.x, s.u);
    if (ray) out += fmt::format("{},", *ray);
    // %.17g: round-trips doubles exactly.
    out += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", s.lambda, x[0], x[1],
                       x[2], x[3], u[0], u[1], u[2], u[3]);
    if (with_tetrad)
      for (int a = 0; a < 4; ++a) {
        const Vec4 e = scene_vector(spacetime, s.x, s.e[a]);
        for (int m = 0; m < 4; ++m) out += fmt::format(",{:.17g}", e[m]);
      }
    out += '\n';
  }
}

namespace {

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

}  // namespace

GeodesicCsv read_geodesic_csv(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument(fmt::format("{}: cannot be read", file.string()));
  // Lines are read with a bounded length, so a file of one enormous line
  // costs no more memory than a short one.
  LineReader reader(in, max_csv_line);
  auto next_line = [&]() -> std::optional<std::string> {
    const auto l = reader.next();
    if (!l) return std::nullopt;
    if (l->too_long)
      throw std::invalid_argument(fmt::format("{}:{}: the line is longer than {} bytes: not a `lightcone geodesic` CSV",
                                              file.string(), l->number, max_csv_line));
    std::string text(l->text);
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return text;
  };
  GeodesicCsv csv;
  // Comments before the header; the chart line among them.
  long number = 0;
  std::optional<std::string> first;
  while ((first = next_line())) {
    ++number;
    if (!first->starts_with('#')) break;
    constexpr std::string_view tag = "# chart: ";
    if (!first->starts_with(tag)) continue;
    const std::string name = first->substr(tag.size(), first->find(' ', tag.size()) - tag.size());
    std::string known;
    for (std::size_t c = 0; c < csv_chart_names.size(); ++c) {
      if (name == csv_chart_names[c]) csv.chart = static_cast<SceneChart>(c);
      known += fmt::format("{}{}", c == 0 ? "" : " or ", csv_chart_names[c]);
    }
    if (!csv.chart)
      throw std::invalid_argument(
          fmt::format("{}:{}: chart '{}' is not one lightcone knows ({}): correct the line, or remove it and give plot "
                      "--coordinates",
                      file.string(), number, name, known));
  }
  if (!first) throw std::invalid_argument(fmt::format("{}: empty (expected a `lightcone geodesic` CSV)", file.string()));
  const long header_line = number;
  const std::vector<std::string> header = split_commas(*first);
  auto column = [&](const std::string& name) -> std::optional<std::size_t> {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return k;
    return std::nullopt;
  };
  const std::optional<std::size_t> ray = column("ray");
  std::array<std::size_t, 4> x{};
  for (int m = 0; m < 4; ++m) {
    const auto k = column(fmt::format("x{}", m));
    if (!k)
      throw std::invalid_argument(fmt::format("{}:{}: no column x{} (expected the header of a `lightcone geodesic` CSV, "
                                              "[ray,]lambda,x0,x1,x2,x3,...)",
                                              file.string(), header_line, m));
    x[static_cast<std::size_t>(m)] = *k;
  }
  std::vector<CsvCurve>& curves = csv.curves;
  for (std::optional<std::string> row; (row = next_line());) {
    ++number;
    const std::string& line = *row;
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_commas(line);
    if (cells.size() != header.size())
      throw std::invalid_argument(fmt::format("{}:{}: {} columns, the header has {}", file.string(), number,
                                              cells.size(), header.size()));
    auto number_at = [&](std::size_t k) {
      double v = 0.0;
      const std::string& c = cells[k];
      const auto [end, ec] = std::from_chars(c.data(), c.data() + c.size(), v);
      if (ec != std::errc() || end != c.data() + c.size() || !std::isfinite(v))
        throw std::invalid_argument(
            fmt::format("{}:{}: column {} is '{}', not a finite number", file.string(), number, header[k], c));
      return v;
    };
    // A ray number outside int's range would not convert (undefined behaviour).
    const double id = ray ? number_at(*ray) : 1.0;
    if (!(id >= 1.0 && id <= 1e9 && id == std::floor(id)))
      throw std::invalid_argument(fmt::format("{}:{}: column ray is '{}', not a whole number from 1 to 1e9",
                                              file.string(), number, cells[*ray]));
    if (curves.empty() || curves.back().ray != static_cast<int>(id)) curves.push_back({static_cast<int>(id), {}, {}});
    curves.back().events.push_back({number_at(x[0]), number_at(x[1]), number_at(x[2]), number_at(x[3])});
    curves.back().lines.push_back(number);
  }
  if (curves.empty()) throw std::invalid_argument(fmt::format("{}: a header but no rows", file.string()));
  return csv;
}

}  // namespace lc
