#pragma once
// A catalogue of stars as points: where each is on the sky, how bright, what
// colour.  Read from KStars' text catalogue (`stars.dat`: Hipparcos and
// Tycho stars to V = 9, J2000; Debian's kstars-data installs it as
// /usr/share/kstars/stars.dat under the GPL, so lightcone reads it where it
// is installed and ships none of it).

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace lc {

struct CatalogueStar {
  double ra = 0.0, dec = 0.0;  // right ascension and declination, radians (J2000)
  double v_mag = 0.0;          // apparent visual magnitude V
  double b_v = 0.0;            // colour index B - V (magnitudes)
};

// A malformed catalogue: the message names the file, the line and the field.
class CatalogueError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The longest catalogue line read (KStars' are at most 101 bytes): a longer
// one is refused before it is held whole (a file of one 2 GB line is not a
// catalogue).
inline constexpr std::size_t max_catalogue_line = 1024;

// The stars of `file` (KStars stars.dat text format) no fainter than
// `faintest` (V), in the file's order.  Lines starting with '#' are
// comments.  A data line holds, by 0-based column: RA `hhmmss.ss` at 0,
// Dec `sddmmss.s` at 10 (the sign always written), V at 46 (5 wide), B - V
// at 51 (5 wide); the rest (proper motion, parallax, spectral type, names)
// is not read.  Every number must be finite and in its range.  Throws
// CatalogueError for a file that cannot be read, a line that does not parse
// or is longer than max_catalogue_line, when more than `max_stars` stars
// pass, and when none does ("0 stars read from FILE", with why).
std::vector<CatalogueStar> read_star_catalogue(const std::filesystem::path& file, double faintest,
                                               std::size_t max_stars);

// The effective temperature (K) of a star of colour index B - V:
// Ballesteros (2012, EPL 97, 34008), T = 4600 (1 / (0.92 (B-V) + 1.7) +
// 1 / (0.92 (B-V) + 0.62)), a blackbody fit good over main-sequence colours
// (B - V from -0.4 to 2); outside that the colour is clamped to it.
double star_temperature(double b_v);

}  // namespace lc
