#include "stars/star_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/constants.hpp"
#include "stars/pass_constants.hpp"

namespace lc {

StarSearch::StarSearch(const RayGrid& grid, const StarField& field, double cos_max)
    : grid_(grid),
      field_(field),
      cos_max_(cos_max),
      cos_wide_(std::cos(wide_patch_radius)),
      cos_plane_(std::cos(plane_tile_radius)),
      patches_(static_cast<std::size_t>(star_tile * star_tile)) {}

void StarSearch::make_nodes(int ti, int tj, int i1, int j1) {
  nodes_origin_i_ = ti;
  nodes_origin_j_ = tj;
  nodes_width_ = i1 - ti + 1;
  nodes_.resize(static_cast<std::size_t>(nodes_width_ * (j1 - tj + 1)));
  for (int j = tj; j <= j1; ++j)
    for (int i = ti; i <= i1; ++i) nodes_[static_cast<std::size_t>((j - tj) * nodes_width_ + (i - ti))] = grid_.at(i, j);
}

const GridNode& StarSearch::node(int i, int j) const {
  return nodes_[static_cast<std::size_t>((j - nodes_origin_j_) * nodes_width_ + (i - nodes_origin_i_))];
}

void StarSearch::tile(int ti, int tj, const PatchStars& report) {
  const int i1 = std::min(grid_.width(), ti + star_tile), j1 = std::min(grid_.height(), tj + star_tile);
  make_nodes(ti, tj, i1, j1);
  Vec3 sum{0, 0, 0};
  int known = 0;
  for (const GridNode& n : nodes_)
    if (n.known) {
      for (int m = 0; m < 3; ++m) sum[m] += n.sky[m];
      ++known;
    }
  if (known < 4) return;
  if (norm3(sum) > 0.0) {
    const Vec3 centre = unit3(sum);
    double least = 1.0;
    for (const GridNode& n : nodes_)
      if (n.known) least = std::min(least, dot3(n.sky, centre));
    if (least >= cos_plane_) {
      search_in_plane(ti, tj, i1, j1, centre, least, report);
      return;
    }
  }
  search_across_jump(ti, tj, i1, j1, report);
}

void StarSearch::search_in_plane(int ti, int tj, int i1, int j1, const Vec3& centre, double least,
                                 const PatchStars& report) {
  std::vector<std::size_t>& found = found_;
  found.clear();
  field_.bins().near(centre, std::acos(least), [&](std::size_t s) {
    if (dot3(field_.stars()[s].direction, centre) >= least) found.push_back(s);
  });
  if (found.empty()) return;
  const Vec3 e1 = unit3(cross3(centre, std::abs(centre[2]) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0}));
  const Vec3 e2 = cross3(centre, e1);
  auto project = [&](const Vec3& v) {
    const double h = dot3(v, centre);
    return std::array<double, 2>{dot3(v, e1) / h, dot3(v, e2) / h};
  };
  std::vector<std::array<double, 2>>& flat = flat_;
  flat.resize(nodes_.size());
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    if (nodes_[k].known) flat[k] = project(nodes_[k].sky);
  std::vector<Placed>& at = placed_;
  at.clear();
  for (const std::size_t s : found) {
    const auto p = project(field_.stars()[s].direction);
    at.push_back({p[0], p[1], s});
  }
  std::sort(at.begin(), at.end(), [](const Placed& a, const Placed& b) { return a.x < b.x; });
  auto flat_at = [&](int i, int j) -> const std::array<double, 2>& {
    return flat[static_cast<std::size_t>((j - tj) * nodes_width_ + (i - ti))];
  };
  std::vector<std::size_t>& here = here_;
  for (int j = tj; j < j1; ++j)
    for (int i = ti; i < i1; ++i) {
      if (!node(i, j).known || !node(i + 1, j).known || !node(i + 1, j + 1).known || !node(i, j + 1).known) continue;
      const auto &a = flat_at(i, j), &b = flat_at(i + 1, j), &c = flat_at(i + 1, j + 1), &d = flat_at(i, j + 1);
      // The box, a hair wider: locate decides on its edge.
      const double x0 = std::min({a[0], b[0], c[0], d[0]}), x1 = std::max({a[0], b[0], c[0], d[0]});
      const double y0 = std::min({a[1], b[1], c[1], d[1]}), y1 = std::max({a[1], b[1], c[1], d[1]});
      const double slack = 1e-9 * (x1 - x0 + y1 - y0) + 1e-15;
      here.clear();
      auto k = std::lower_bound(at.begin(), at.end(), x0 - slack, [](const Placed& p, double x) { return p.x < x; });
      for (; k != at.end() && k->x <= x1 + slack; ++k)
        if (k->y >= y0 - slack && k->y <= y1 + slack) here.push_back(k->star);
      if (here.empty()) continue;
      if (const auto q = make_patch(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1), cos_max_))
        report(i, j, *q, here);
    }
}

void StarSearch::search_across_jump(int ti, int tj, int i1, int j1, const PatchStars& report) {
  auto patch = [&](int i, int j) -> std::optional<SkyPatch>& {
    return patches_[static_cast<std::size_t>((j - tj) * star_tile + (i - ti))];
  };
  for (int j = tj; j < j1; ++j)
    for (int i = ti; i < i1; ++i) patch(i, j) = make_patch(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1), cos_max_);
  // A wide patch (the lens spreads it over more than a bin) asks the bins
  // alone, so that the blocks' caps stay as small as their patches are.
  std::vector<std::size_t>& near = here_;
  for (int j = tj; j < j1; ++j)
    for (int i = ti; i < i1; ++i) {
      auto& q = patch(i, j);
      if (!q || q->cos_reach >= cos_wide_) continue;
      near.clear();
      field_.bins().near(q->centre, std::acos(q->cos_reach), [&](std::size_t s) { near.push_back(s); });
      if (!near.empty()) report(i, j, *q, near);
      q.reset();
    }
  search_block(ti, tj, ti, tj, i1, j1, nullptr, report);
}

void StarSearch::search_block(int ti, int tj, int i0, int j0, int i1, int j1, const std::vector<std::size_t>* from,
                              const PatchStars& report) {
  auto patch = [&](int i, int j) -> const std::optional<SkyPatch>& {
    return patches_[static_cast<std::size_t>((j - tj) * star_tile + (i - ti))];
  };
  Vec3 sum{0, 0, 0};
  int count = 0;
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i)
      if (const auto& q = patch(i, j)) {
        for (int m = 0; m < 3; ++m) sum[m] += q->centre[m];
        ++count;
      }
  if (count == 0 || norm3(sum) == 0.0) return;
  const Vec3 centre = unit3(sum);
  double radius = 0.0;
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i)
      if (const auto& q = patch(i, j))
        radius = std::max(radius, std::acos(std::clamp(dot3(q->centre, centre), -1.0, 1.0)) +
                                      std::acos(std::clamp(q->cos_reach, -1.0, 1.0)));
  radius = std::min(radius, pi);
  const double cos_radius = std::cos(radius);
  std::vector<std::size_t> candidates;
  auto take = [&](std::size_t s) {
    if (dot3(field_.stars()[s].direction, centre) >= cos_radius) candidates.push_back(s);
  };
  if (from)
    for (const std::size_t s : *from) take(s);
  else
    field_.bins().near(centre, radius, take);
  if (candidates.empty()) return;
  if (candidates.size() > star_block_split_above && count > 1) {
    const int im = (i0 + i1 + 1) / 2, jm = (j0 + j1 + 1) / 2;
    for (const auto& [a0, a1] : {std::pair{i0, im}, std::pair{im, i1}})
      for (const auto& [b0, b1] : {std::pair{j0, jm}, std::pair{jm, j1}})
        if (a0 < a1 && b0 < b1) search_block(ti, tj, a0, b0, a1, b1, &candidates, report);
    return;
  }
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i)
      if (const auto& q = patch(i, j)) report(i, j, *q, candidates);
}

}  // namespace lc
