#pragma once
// Stars binned on the sky, to find those within a small cap quickly: bands
// of equal width in theta (from +z), each cut into cells about as wide in
// phi as the bands are tall.  Memory is one index per star plus the cells,
// whatever the field of view of the frames that look them up.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/tensor.hpp"

namespace lc {

class StarBins {
 public:
  // directions: unit vectors, one per star (indices into it are returned);
  // cell: the bands' width in theta (radians), > 0.
  StarBins(const std::vector<Vec3>& directions, double cell);

  // f(index) for every star whose direction is within `radius` radians of
  // the unit vector `centre`, and for some just beyond (the cells that
  // overlap the cap are visited whole): callers test what they need.
  template <class F>
  void near(const Vec3& centre, double radius, F&& f) const {
    for_cells(centre, radius, [&](std::size_t cell) {
      for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) f(static_cast<std::size_t>(index_[k]));
    });
  }

  std::size_t bytes() const { return index_.size() * sizeof(std::uint32_t) + start_.size() * sizeof(std::uint32_t); }

 private:
  // The cells overlapping the cap, each once.
  template <class G>
  void for_cells(const Vec3& centre, double radius, G&& g) const;
  std::size_t cell_of(double theta, double phi) const;

  int bands_;
  std::vector<int> columns_;          // cells in each band
  std::vector<std::size_t> first_;    // each band's first cell
  std::vector<std::uint32_t> start_;  // each cell's first entry in index_, and the end
  std::vector<std::uint32_t> index_;  // star indices, cell by cell
};

}  // namespace lc

#include "stars/star_bins_impl.hpp"
