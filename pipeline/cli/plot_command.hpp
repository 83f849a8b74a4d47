#pragma once
// `lightcone plot CSV -o FIGURE.svg|png`: the curves of a `lightcone
// geodesic` CSV drawn as a figure through Cairo, in a plane of
// (pseudo-)Cartesian coordinates, with the hole's horizon and an equatorial
// disk if asked for.  With a disk, each ray ends where it first meets the
// disk: solid when its light left the disk's top side, dashed when the
// bottom side (the paper's Figure 2).  Layout: docs/geodesic.md, "Plots".

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geodesic_csv.hpp"

namespace lc {

enum class PlotView { xz, xy, yz };  // the plane drawn: its first axis across, its second up

struct PlotCommand {
  std::filesystem::path csv;
  std::filesystem::path output;  // .svg or .png
  // What the CSV's x1..x3 are, (r, theta, phi) or (x, y, z), for a CSV
  // that does not record its chart (written before it did); unset: the
  // CSV's chart, or bl for such an old one.  A CSV's chart overrides none:
  // the two disagreeing is an error.
  std::optional<SceneChart> coordinates;
  PlotView view = PlotView::xz;
  std::string size = "800x600";
  std::optional<double> extent;                // half the width shown (M); default: every point fits
  std::optional<std::string> disk;             // "INNER:OUTER" in the equatorial plane z = 0
  double horizon = 0.0;                        // radius of the black disc drawn at the origin (0: none)
};

// How a curve is drawn.
enum class LineStyle {
  plain,   // no disk asked for, or the ray never meets it
  top,     // ends on the disk, its light from the disk's top side (solid)
  bottom,  // ... from its bottom side (dashed)
};

struct FigureLine {
  int ray = 1;
  std::vector<std::array<double, 2>> points;  // in the view's plane, coordinates (M)
  LineStyle style = LineStyle::plain;
};

struct DiskRange {
  double inner = 0.0, outer = 0.0;
};

// The curves projected into the view's plane, each cut at its first
// crossing of z = 0 between the disk's radii when a disk is given (the
// crossing linearly interpolated between the samples either side).
std::vector<FigureLine> figure_lines(const std::vector<CsvCurve>& curves, SceneChart coordinates, PlotView view,
                                     const std::optional<DiskRange>& disk);

// Where a point of the view's plane lands in the image (pixels from the
// top left), for a figure of `width` x `height` whose plot area shows
// [-extent, extent] across: the layout the drawing uses, and the tests.
struct FigureFrame {
  int width = 0, height = 0;
  double extent = 1.0;
  double left = 0.0, top = 0.0, side = 0.0;  // the plot area (a square), pixels
  std::array<double, 2> to_pixel(const std::array<double, 2>& p) const;
};
FigureFrame figure_frame(int width, int height, double extent);

int run_plot(const PlotCommand& cmd);

}  // namespace lc
