// storyboard_check CHECK FRAME.exr: checks a rendered frame (with data
// layers, one sample per pixel) against what the storyboard implies.  Exit 0
// when it holds, 1 with the reason when it does not, 2 on bad usage.
//
//   no-shadow      no pixel sees a horizon (hit.kind 2), and some see the sphere (3)
//   shadow         some pixels see a horizon
//   flat-disk      the disk is seen undistorted: in flat spacetime light runs
//                  straight, so the map from pixel to the point of the disk
//                  plane it sees is a projective one (a homography) and the
//                  disk's rims (circles) are ellipses.  Fits the homography to
//                  every disk pixel (centre -> (r cos phi, r sin phi) from
//                  hit.r and hit.phi) and requires the largest miss below
//                  1e-4 M — a lensed disk misses by whole M.  The rays are
//                  traced to ~1e-10, so the fit's miss is rounding, far below.
//
// Independent of the camera's conventions on purpose: any pinhole camera
// gives some homography; only bent light breaks it.

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "image/image_io.hpp"

namespace {

const std::vector<float>& layer(const lc::FrameImage& img, const std::string& name, const char* file) {
  for (const auto& l : img.layers)
    if (l.name == name) return l.values;
  std::fprintf(stderr, "storyboard_check: %s has no %s layer (render with --layers)\n", file, name.c_str());
  std::exit(2);
}

int count_kind(const std::vector<float>& kind, int k) {
  int n = 0;
  for (float v : kind) n += static_cast<int>(std::lround(v)) == k;
  return n;
}

// Solves the n x n system m x = b in place (Gaussian elimination with partial
// pivoting); false when singular.
bool solve(std::vector<std::vector<double>>& m, std::vector<double>& b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(m[r][c]) > std::abs(m[p][c])) p = r;
    if (std::abs(m[p][c]) < 1e-300) return false;
    std::swap(m[p], m[c]);
    std::swap(b[p], b[c]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = m[r][c] / m[c][c];
      for (std::size_t k = c; k < n; ++k) m[r][k] -= f * m[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = n; c-- > 0;) {
    for (std::size_t k = c + 1; k < n; ++k) b[c] -= m[c][k] * b[k];
    b[c] /= m[c][c];
  }
  return true;
}

// Largest distance (M) between the disk point each disk pixel sees and the
// best-fitting homography's prediction.  Pixel coordinates are scaled to
// about [-1, 1] to keep the normal equations well conditioned.
int flat_disk(const lc::FrameImage& img, const char* file) {
  const auto& kind = layer(img, "hit.kind", file);
  const auto& r = layer(img, "hit.r", file);
  const auto& phi = layer(img, "hit.phi", file);
  struct Sample { double u, v, x, y; };
  std::vector<Sample> s;
  const double half = 0.5 * img.width;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * img.width + i;
      if (std::lround(kind[p]) != 1) continue;
      s.push_back({(i + 0.5 - half) / half, (j + 0.5 - 0.5 * img.height) / half, r[p] * std::cos(phi[p]),
                   r[p] * std::sin(phi[p])});
    }
  if (s.size() < 20) {
    std::fprintf(stderr, "storyboard_check: %s: only %zu disk pixels; too few to judge\n", file, s.size());
    return 1;
  }
  // x = (h0 u + h1 v + h2) / (h6 u + h7 v + 1), y = (h3 u + h4 v + h5) / (...),
  // linearised: h0 u + h1 v + h2 - x h6 u - x h7 v = x, and likewise for y.
  std::vector<std::vector<double>> ata(8, std::vector<double>(8, 0.0));
  std::vector<double> atb(8, 0.0);
  auto add = [&](const std::array<double, 8>& row, double rhs) {
    for (int a = 0; a < 8; ++a) {
      for (int b = 0; b < 8; ++b) ata[a][b] += row[a] * row[b];
      atb[a] += row[a] * rhs;
    }
  };
  for (const Sample& q : s) {
    add({q.u, q.v, 1, 0, 0, 0, -q.x * q.u, -q.x * q.v}, q.x);
    add({0, 0, 0, q.u, q.v, 1, -q.y * q.u, -q.y * q.v}, q.y);
  }
  if (!solve(ata, atb)) {
    std::fprintf(stderr, "storyboard_check: %s: the disk pixels fit no homography (degenerate)\n", file);
    return 1;
  }
  const std::vector<double>& h = atb;
  double worst = 0, rmin = 1e300, rmax = 0;
  for (const Sample& q : s) {
    const double w = h[6] * q.u + h[7] * q.v + 1;
    const double x = (h[0] * q.u + h[1] * q.v + h[2]) / w, y = (h[3] * q.u + h[4] * q.v + h[5]) / w;
    worst = std::max(worst, std::hypot(x - q.x, y - q.y));
    rmin = std::min(rmin, std::hypot(q.x, q.y));
    rmax = std::max(rmax, std::hypot(q.x, q.y));
  }
  std::printf("%s: %zu disk pixels, r %.3f to %.3f, largest miss of a projective map %.3g M\n", file, s.size(), rmin,
              rmax, worst);
  if (worst > 1e-4) {
    std::fprintf(stderr, "storyboard_check: %s: the disk is distorted (a projective map misses by %.3g M)\n", file, worst);
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: storyboard_check no-shadow|shadow|flat-disk FRAME.exr\n");
    return 2;
  }
  const std::string check = argv[1];
  const char* file = argv[2];
  lc::FrameImage img;
  try {
    img = lc::read_exr(file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "storyboard_check: %s\n", e.what());
    return 2;
  }
  if (check == "flat-disk") return flat_disk(img, file);
  const auto& kind = layer(img, "hit.kind", file);
  const int horizon = count_kind(kind, 2), sphere = count_kind(kind, 3);
  std::printf("%s: %d horizon pixels, %d sphere pixels\n", file, horizon, sphere);
  if (check == "no-shadow") {
    if (horizon != 0 || sphere == 0) {
      std::fprintf(stderr, "storyboard_check: %s: expected no shadow and the sphere in view\n", file);
      return 1;
    }
    return 0;
  }
  if (check == "shadow") return horizon > 0 ? 0 : 1;
  std::fprintf(stderr, "storyboard_check: unknown check '%s'\n", check.c_str());
  return 2;
}
