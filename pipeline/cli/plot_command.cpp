#include "plot_command.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "store/durable_file.hpp"
#include "job/image_size.hpp"

namespace lc {
namespace {

// Every point drawn, the disk and the extent must be within this many M of
// the origin: far beyond any ray a spec traces (they escape at ~1000 M),
// small enough that the figure's scale and Cairo's coordinates hold.
constexpr double max_plot_coordinate = 1e12;

// An event's (pseudo-)Cartesian position: Boyer–Lindquist (r, theta, phi)
// taken as spherical coordinates (the paper's Figure 1), or (x, y, z).
std::array<double, 3> cartesian(const std::array<double, 4>& e, SceneChart c) {
  if (c == SceneChart::cartesian) return {e[1], e[2], e[3]};
  const double r = e[1], th = e[2], ph = e[3];
  return {r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th)};
}

std::array<double, 2> project(const std::array<double, 3>& p, PlotView v) {
  switch (v) {
    case PlotView::xz: return {p[0], p[2]};
    case PlotView::xy: return {p[0], p[1]};
    case PlotView::yz: return {p[1], p[2]};
  }
  return {};
}

DiskRange parse_disk(const std::string& text) {
  const auto colon = text.find(':');
  DiskRange d;
  auto number = [&](std::string_view s, double& out) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size() && std::isfinite(out);
  };
  if (colon == std::string::npos || !number(std::string_view(text).substr(0, colon), d.inner) ||
      !number(std::string_view(text).substr(colon + 1), d.outer) || !(d.inner >= 0.0) || !(d.outer > d.inner) ||
      d.outer > max_plot_coordinate)
    throw std::invalid_argument(fmt::format(
        "--disk {}: expected INNER:OUTER, two radii with 0 <= INNER < OUTER <= {:g} (e.g. 6:16)", text,
        max_plot_coordinate));
  return d;
}

// A step of 1, 2 or 5 times a power of ten, near `span` / 6.
double tick_step(double span) {
  const double raw = span / 6.0, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10.0 * p;
}

std::string axis_name(PlotView v, int axis) {
  static const char* names[3][2] = {{"x", "z"}, {"x", "y"}, {"y", "z"}};
  return fmt::format("{} / M", names[static_cast<int>(v)][axis]);
}

void draw(cairo_t* cr, const FigureFrame& f, const std::vector<FigureLine>& lines, const PlotCommand& cmd,
          const std::optional<DiskRange>& disk) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  const double E = f.extent;
  // Ticks and their labels, then the frame.
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 12);
  cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
  cairo_set_line_width(cr, 1.0);
  const double step = tick_step(2.0 * E);
  for (double v = std::ceil(-E / step) * step; v <= E + 1e-9 * E; v += step) {
    const double a = std::abs(v) < 1e-9 * step ? 0.0 : v;
    const std::string label = fmt::format("{:g}", a);
    cairo_text_extents_t te;
    cairo_text_extents(cr, label.c_str(), &te);
    const auto [x, y0] = f.to_pixel({a, -E});
    cairo_move_to(cr, x, y0);
    cairo_line_to(cr, x, y0 + 5);
    cairo_stroke(cr);
    cairo_move_to(cr, x - te.width / 2 - te.x_bearing, y0 + 8 + te.height);
    cairo_show_text(cr, label.c_str());
    const auto [x0, y] = f.to_pixel({-E, a});
    cairo_move_to(cr, x0, y);
    cairo_line_to(cr, x0 - 5, y);
    cairo_stroke(cr);
    cairo_move_to(cr, x0 - 8 - te.width - te.x_bearing, y + te.height / 2);
    cairo_show_text(cr, label.c_str());
  }
  cairo_rectangle(cr, f.left, f.top, f.side, f.side);
  cairo_stroke(cr);
  cairo_set_font_size(cr, 13);
  for (int axis = 0; axis < 2; ++axis) {
    const std::string name = axis_name(cmd.view, axis);
    cairo_text_extents_t te;
    cairo_text_extents(cr, name.c_str(), &te);
    cairo_save(cr);
    if (axis == 0) {
      cairo_move_to(cr, f.left + f.side / 2 - te.width / 2, f.top + f.side + 40);
    } else {
      cairo_move_to(cr, f.left - 44, f.top + f.side / 2 + te.width / 2);
      cairo_rotate(cr, -pi / 2);
    }
    cairo_show_text(cr, name.c_str());
    cairo_restore(cr);
  }
  // Inside the frame: the disk, the horizon, the rays.
  cairo_save(cr);
  cairo_rectangle(cr, f.left, f.top, f.side, f.side);
  cairo_clip(cr);
  const double scale = f.side / (2.0 * E);  // pixels per M
  if (disk) {
    cairo_set_source_rgb(cr, 0.93, 0.6, 0.2);
    if (cmd.view == PlotView::xy) {
      const auto [cx, cy] = f.to_pixel({0.0, 0.0});
      cairo_new_path(cr);
      cairo_arc(cr, cx, cy, disk->outer * scale, 0, two_pi);
      cairo_arc_negative(cr, cx, cy, disk->inner * scale, two_pi, 0);
      cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
      cairo_fill(cr);
    } else {
      cairo_set_line_width(cr, 4.0);
      for (const double sign : {-1.0, 1.0}) {
        const auto a = f.to_pixel({sign * disk->inner, 0.0}), b = f.to_pixel({sign * disk->outer, 0.0});
        cairo_move_to(cr, a[0], a[1]);
        cairo_line_to(cr, b[0], b[1]);
        cairo_stroke(cr);
      }
    }
  }
  if (cmd.horizon > 0.0) {
    const auto [cx, cy] = f.to_pixel({0.0, 0.0});
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_new_path(cr);
    cairo_arc(cr, cx, cy, cmd.horizon * scale, 0, two_pi);
    cairo_fill(cr);
  }
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const FigureLine& l : lines) {
    if (l.points.size() < 2) continue;
    const double dash[] = {7.0, 4.0};
    cairo_set_dash(cr, dash, l.style == LineStyle::bottom ? 2 : 0, 0.0);
    if (l.style == LineStyle::plain && disk) {
      cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
      cairo_set_line_width(cr, 1.0);
    } else {
      cairo_set_source_rgb(cr, 0.1, 0.25, 0.6);
      cairo_set_line_width(cr, 1.5);
    }
    cairo_new_path(cr);
    for (const auto& p : l.points) {
      const auto q = f.to_pixel(p);
      cairo_line_to(cr, q[0], q[1]);
    }
    cairo_stroke(cr);
  }
  cairo_restore(cr);
  if (disk) {
    cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
    cairo_set_font_size(cr, 12);
    cairo_move_to(cr, f.left + 6, f.top + 16);
    cairo_show_text(cr, "solid: light from the disk's top side; dashed: from its bottom side");
  }
}

void check(cairo_status_t status, const std::filesystem::path& out) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(fmt::format("-o {}: Cairo could not draw or write it: {}", out.string(),
                                         cairo_status_to_string(status)));
}

// Cairo writes the figure through this, into the DurableFile: a write
// error is then the file's own ("cannot write DIR/x.png: No space left on
// device"), where Cairo's file writers say only "error while writing to
// output stream".  The exception is kept, not thrown through Cairo's C.
struct FigureSink {
  DurableFile& file;
  std::exception_ptr error;
  static cairo_status_t write(void* self, const unsigned char* data, unsigned int length) {
    auto* sink = static_cast<FigureSink*>(self);
    if (sink->error) return CAIRO_STATUS_WRITE_ERROR;
    try {
      sink->file.write(std::string_view(reinterpret_cast<const char*>(data), length));
      return CAIRO_STATUS_SUCCESS;
    } catch (...) {
      sink->error = std::current_exception();
      return CAIRO_STATUS_WRITE_ERROR;
    }
  }
};

// Throws naming the CSV's line of the first point whose (pseudo-)Cartesian
// coordinates are beyond max_plot_coordinate (e.g. r = 1e308: sin and cos
// keep it finite, but the figure's width overflows to infinity).
void check_coordinates(const std::vector<CsvCurve>& curves, SceneChart coordinates, const std::filesystem::path& csv) {
  for (const CsvCurve& c : curves)
    for (std::size_t i = 0; i < c.events.size(); ++i) {
      const auto p = cartesian(c.events[i], coordinates);
      if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) &&
          std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}) <= max_plot_coordinate)
        continue;
      throw std::invalid_argument(fmt::format(
          "{}:{}: the point ({:g}, {:g}, {:g}) M is too far out: plot draws points within {:g} M of the origin "
          "(cut the CSV's rows beyond it)",
          csv.string(), i < c.lines.size() ? c.lines[i] : 0L, p[0], p[1], p[2], max_plot_coordinate));
    }
}

}  // namespace

std::array<double, 2> FigureFrame::to_pixel(const std::array<double, 2>& p) const {
  return {left + (p[0] + extent) / (2.0 * extent) * side, top + (extent - p[1]) / (2.0 * extent) * side};
}

FigureFrame figure_frame(int width, int height, double extent) {
  // Room for the tick labels and axis names left and below; the plot area
  // a square (equal scales), centred in what is left.
  constexpr double margin_left = 64, margin_right = 16, margin_top = 16, margin_bottom = 56;
  FigureFrame f{width, height, extent, 0, 0, 0};
  const double w = width - margin_left - margin_right, h = height - margin_top - margin_bottom;
  f.side = std::min(w, h);
  f.left = margin_left + (w - f.side) / 2;
  f.top = margin_top + (h - f.side) / 2;
  return f;
}

std::vector<FigureLine> figure_lines(const std::vector<CsvCurve>& curves, SceneChart coordinates, PlotView view,
                                     const std::optional<DiskRange>& disk) {
  std::vector<FigureLine> out;
  for (const CsvCurve& c : curves) {
    FigureLine line{c.ray, {}, LineStyle::plain};
    std::array<double, 3> prev{};
    for (std::size_t i = 0; i < c.events.size(); ++i) {
      const auto p = cartesian(c.events[i], coordinates);
      if (disk && i > 0 && (prev[2] > 0.0) != (p[2] > 0.0) && prev[2] != 0.0) {
        const double s = prev[2] / (prev[2] - p[2]);
        const std::array<double, 3> hit = {prev[0] + s * (p[0] - prev[0]), prev[1] + s * (p[1] - prev[1]), 0.0};
        const double rho = std::hypot(hit[0], hit[1]);
        if (rho >= disk->inner && rho <= disk->outer) {
          line.points.push_back(project(hit, view));
          line.style = prev[2] > 0.0 ? LineStyle::top : LineStyle::bottom;
          break;
        }
      }
      line.points.push_back(project(p, view));
      prev = p;
    }
    out.push_back(std::move(line));
  }
  return out;
}

int run_plot(const PlotCommand& cmd) {
  std::string ext = cmd.output.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return std::tolower(ch); });
  if (ext != ".svg" && ext != ".png")
    throw std::invalid_argument(
        fmt::format("-o {}: a figure is written as SVG or PNG (name it .svg or .png)", cmd.output.string()));
  const auto [width, height] = parse_image_size(cmd.size, "--size");
  if (width < 200 || height < 150 || width > max_frame_side || height > max_frame_side)
    throw std::invalid_argument(fmt::format("--size {}: a figure is 200x150 to {}x{} pixels", cmd.size, max_frame_side,
                                            max_frame_side));
  if (cmd.extent && !(*cmd.extent > 0.0 && *cmd.extent <= max_plot_coordinate))
    throw std::invalid_argument(
        fmt::format("--extent {:g}: must be a positive number of M, at most {:g}", *cmd.extent, max_plot_coordinate));
  if (!(cmd.horizon >= 0.0 && cmd.horizon <= max_plot_coordinate))
    throw std::invalid_argument(
        fmt::format("--horizon {:g}: must be a radius >= 0, at most {:g} M", cmd.horizon, max_plot_coordinate));
  const std::optional<DiskRange> disk = cmd.disk ? std::optional(parse_disk(*cmd.disk)) : std::nullopt;

  const GeodesicCsv csv = read_geodesic_csv(cmd.csv);
  if (csv.chart && cmd.coordinates && *csv.chart != *cmd.coordinates)
    throw std::invalid_argument(fmt::format(
        "--coordinates {}: {} records its chart as {} (its first line); drop --coordinates, which is for CSVs that do "
        "not say",
        csv_chart_name(*cmd.coordinates), cmd.csv.string(), csv_chart_name(*csv.chart)));
  const SceneChart chart = csv.chart.value_or(cmd.coordinates.value_or(SceneChart::polar));
  const std::vector<CsvCurve>& curves = csv.curves;
  check_coordinates(curves, chart, cmd.csv);
  const std::vector<FigureLine> lines = figure_lines(curves, chart, cmd.view, disk);
  double extent = 0.0;
  if (cmd.extent) {
    extent = *cmd.extent;
  } else {
    for (const auto& l : lines)
      for (const auto& p : l.points) extent = std::max({extent, std::abs(p[0]), std::abs(p[1])});
    if (disk) extent = std::max(extent, disk->outer);
    extent = std::max({1.05 * extent, 1.05 * cmd.horizon, 1e-6});
  }
  const FigureFrame frame = figure_frame(width, height, extent);

  DurableFile file(cmd.output);
  FigureSink sink{file, nullptr};
  cairo_surface_t* surface = ext == ".svg"
                                 ? cairo_svg_surface_create_for_stream(&FigureSink::write, &sink, width, height)
                                 : cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  // Sizes in pixels, as asked for (Cairo's SVG default is points).
  if (ext == ".svg") cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
  cairo_t* cr = cairo_create(surface);
  draw(cr, frame, lines, cmd, disk);
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  cairo_status_t written = drawn;
  if (drawn == CAIRO_STATUS_SUCCESS) {
    if (ext == ".png") written = cairo_surface_write_to_png_stream(surface, &FigureSink::write, &sink);
    cairo_surface_finish(surface);
    if (written == CAIRO_STATUS_SUCCESS) written = cairo_surface_status(surface);
  }
  cairo_surface_destroy(surface);
  if (sink.error) std::rethrow_exception(sink.error);
  check(written, cmd.output);
  file.commit();
  int ended = 0, top = 0, bottom = 0;
  for (const auto& l : lines) {
    ended += l.style != LineStyle::plain;
    top += l.style == LineStyle::top;
    bottom += l.style == LineStyle::bottom;
  }
  fmt::print(stderr, "plot: {} curves{} -> {} ({}x{}, {:.4g} M across)\n", lines.size(),
             disk ? fmt::format(", {} end on the disk ({} from its top side, {} from its bottom)", ended, top, bottom)
                  : "",
             cmd.output.string(), width, height, 2.0 * extent);
  return 0;
}

}  // namespace lc
