#include "stars/star_catalogue.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/line_reader.hpp"

namespace lc {

namespace {

// The digits in s[from, from + n) as a number, or nullopt when any is not
// a digit (or the line is too short).
std::optional<int> digits(std::string_view s, std::size_t from, std::size_t n) {
  if (s.size() < from + n) return std::nullopt;
  int v = 0;
  for (std::size_t k = from; k < from + n; ++k) {
    if (!std::isdigit(static_cast<unsigned char>(s[k]))) return std::nullopt;
    v = 10 * v + (s[k] - '0');
  }
  return v;
}

// A finite decimal number in s[from, from + n) ("-1.44", "00.03"), or
// nullopt.  std::from_chars also reads "nan" and "inf", which every range
// check after it would let through (a comparison with NaN is false).
std::optional<double> decimal(std::string_view s, std::size_t from, std::size_t n) {
  if (s.size() < from + n) return std::nullopt;
  std::string_view f = s.substr(from, n);
  while (!f.empty() && f.front() == ' ') f.remove_prefix(1);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

std::vector<CatalogueStar> read_star_catalogue(const std::filesystem::path& file, double faintest,
                                               std::size_t max_stars) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw CatalogueError(fmt::format("{}: {}", file.string(),
                                     std::filesystem::exists(file, ec) ? "not a regular file: a star catalogue is one"
                                                                       : "no such star catalogue"));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw CatalogueError(fmt::format("{}: cannot read the star catalogue", file.string()));
  std::vector<CatalogueStar> out;
  LineReader lines(in, max_catalogue_line);
  long number = 0, data_lines = 0;
  auto fail = [&](const char* what, const char* form) {
    throw CatalogueError(
        fmt::format("{}:{}: {} is not {} (KStars stars.dat format: docs/stars.md)", file.string(), number, what, form));
  };
  while (const auto line = lines.next()) {
    number = line->number;
    if (line->too_long)
      throw CatalogueError(fmt::format("{}:{}: the line is longer than {} bytes (a stars.dat line is about 100): not "
                                       "a star catalogue (KStars stars.dat format: docs/stars.md)",
                                       file.string(), number, max_catalogue_line));
    const std::string_view s = line->text;
    if (s.empty() || s[0] == '#') continue;
    ++data_lines;
    const auto hh = digits(s, 0, 2), mm = digits(s, 2, 2);
    const auto ss = decimal(s, 4, 5);
    // (Seconds of 60.00 occur: rounding in the catalogue.)
    if (!hh || !mm || !ss || *hh > 23 || *mm > 59 || *ss < 0.0 || *ss > 60.0) fail("the right ascension (columns 1-9)", "hhmmss.ss");
    const char sign = s.size() > 10 ? s[10] : ' ';
    const auto dd = digits(s, 11, 2), dm = digits(s, 13, 2);
    const auto ds = decimal(s, 15, 4);
    if ((sign != '+' && sign != '-') || !dd || !dm || !ds || *dd > 90 || *dm > 59 || *ds < 0.0 || *ds > 60.0)
      fail("the declination (columns 11-19)", "sddmmss.s with its sign");
    // The ranges catch columns that drifted: a value read half from its
    // neighbour is out of them.
    const auto v = decimal(s, 46, 5);
    if (!v || *v < -2.0 || *v > 30.0) fail("the magnitude V (columns 47-51)", "a number from -2 to 30");
    const auto bv = decimal(s, 51, 5);
    if (!bv || *bv < -1.0 || *bv > 6.0) fail("the colour index B-V (columns 52-56)", "a number from -1 to 6");
    if (*v > faintest) continue;
    CatalogueStar star;
    star.ra = 15.0 * (*hh + *mm / 60.0 + *ss / 3600.0) * degree;
    star.dec = (sign == '-' ? -1.0 : 1.0) * (*dd + *dm / 60.0 + *ds / 3600.0) * degree;
    if (std::abs(star.dec) > 0.5 * pi) fail("the declination (columns 11-19)", "within +-90 degrees");
    star.v_mag = *v;
    star.b_v = *bv;
    if (out.size() == max_stars)
      throw CatalogueError(fmt::format("{}: more than {} stars brighter than V = {:g}: choose a brighter limit",
                                       file.string(), max_stars, faintest));
    out.push_back(star);
  }
  if (lines.failed()) throw CatalogueError(fmt::format("{}: reading failed after line {}", file.string(), number));
  // A catalogue that gives no star would render a starless sky without a
  // word: say why instead.
  if (out.empty())
    throw CatalogueError(
        data_lines == 0
            ? fmt::format("{}: 0 stars read from it: it holds no star line, only comments or nothing "
                          "(KStars stars.dat format: docs/stars.md)",
                          file.string())
            : fmt::format("{}: 0 stars read from it: none of its {} stars is as bright as V = {:g}: raise "
                          "`faintest`",
                          file.string(), data_lines, faintest));
  return out;
}

double star_temperature(double b_v) {
  const double c = 0.92 * std::clamp(b_v, -0.4, 2.0);
  return 4600.0 * (1.0 / (c + 1.7) + 1.0 / (c + 0.62));
}

}  // namespace lc
