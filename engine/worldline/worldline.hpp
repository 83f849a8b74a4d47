#pragma once
// A free-falling worldline integrated once per shot (GSL reference solver,
// tetrad parallel-transported), then sampled by proper time (observers) or
// by coordinate time (objects met by rays).  Stored at uniform proper-time
// steps and interpolated with cubic Hermite polynomials (position with its
// 4-velocity as derivative).  For the rays' many centre lookups it is also
// resampled once at uniform coordinate-time steps (position and 4-velocity,
// each Hermite with its own t-derivative), so such a lookup is an index and
// a few dozen flops: no search, no Newton.

#include <vector>

#include "eye/tetrad.hpp"
#include "worldline/worldline_spec.hpp"

namespace lc {

struct WorldlineEvent {
  Vec4 x;        // trace coordinates
  Tetrad frame;  // e[0] = 4-velocity; legs orthonormal
  double tau;    // proper time since the start
};

class Worldline {
 public:
  // Integrates the spec in the chart rays are traced in (outgoing
  // Kerr–Schild for Kerr).  Throws std::invalid_argument naming spec.where
  // when the start is unphysical or the body is captured before `duration`.
  static Worldline integrate(const WorldlineSpec& spec);

  double duration() const { return duration_; }
  double start_time() const { return samples_.front().x[0]; }  // trace coordinate time
  double end_time() const { return samples_.back().x[0]; }

  // The event at proper time tau in [0, duration] (clamped).
  WorldlineEvent at_proper_time(double tau) const;
  // The event at trace coordinate time t; before the start the body is
  // taken to have been held at rest at its start (the frame of the start
  // event, no motion); after the end: clamped to the end.
  WorldlineEvent at_coordinate_time(double t) const;
  // Proper time at trace coordinate time t (clamped to [0, duration]).
  double proper_time_at(double t) const;
  // Only the position x and 4-velocity u at trace coordinate time t (as
  // at_coordinate_time, without the frame's metric and Gram–Schmidt):
  // what finding the event simultaneous with a ray point needs.
  void centre_at_coordinate_time(double t, Vec4& x, Vec4& u) const;

  // Axis-aligned spatial box of the positions over the coordinate-time
  // interval [t0, t1] (any order): the tube the object's centre stays in.
  void bounds(double t0, double t1, Vec3& lo, Vec3& hi) const;

  // The fastest the centre moves in coordinates, |dx/dt|, at any time (the
  // interpolant's, not only the samples'; before the start and after the
  // end it stands still).
  double top_coordinate_speed() const { return top_speed_; }

  // How far, in coordinates, a point of a sphere of proper radius `radius`
  // riding this worldline may be from the centre at the point's own
  // coordinate time: the spacetime tube's radius (objects/sphere_body.hpp).
  // The sphere is the ball of its rest space through the centre event
  // (objects/sphere_intersection.hpp); a point of it d away from the centre event
  // C(t_c) lies, in coordinates, d slid along u from where the centre is at
  // the point's time t_c + d^t, off by the centre's change of velocity over
  // d^t: at most stretch R + A (tilt R)^2 / 2 with A the interpolant's top
  // coordinate acceleration within tilt R of t_c (rest_space_span; before
  // the release the centre stands still, which adds its release speed times
  // tilt R).  The largest over the table's samples, 5% more for how the
  // rest space turns between samples.
  double coordinate_extent(double radius) const;

  const Spacetime& spacetime() const { return spacetime_; }
  // Memory held by the samples and tables (for ShotResources' budget).
  std::size_t bytes() const {
    return samples_.capacity() * sizeof(Sample) + by_time_.capacity() * sizeof(TimeSample) +
           spans_.capacity() * sizeof(RestSpaceSpan) + chunk_bounds_.capacity() * sizeof(chunk_bounds_[0]) +
           chunk_acceleration_.capacity() * sizeof(double);
  }

  // Events where the distance from the origin (Boyer–Lindquist r for Kerr,
  // |x| otherwise) has a local maximum, in order: the turning points of an
  // oscillation or the apocentres of an orbit, located by golden-section
  // search on the interpolant (the maximum is flat: the time is good to
  // ~sqrt(interpolation error), ~1e-6).  Shots time animation by them.
  std::vector<WorldlineEvent> apocentres() const;
  // Scene time (Boyer–Lindquist t for Kerr) of a trace-coordinate event.
  double scene_time(const Vec4& x) const;

 private:
  // The sample step [i, i + 1] holding trace coordinate time t.
  std::size_t sample_index_at(double t) const;
  // Index of the coordinate-time table step holding t, clamped to the table.
  std::size_t time_index(double t) const;
  // The top |d2x/dt2| of the coordinate-time interpolant on its step k.
  double step_acceleration(std::size_t k) const;

  struct Sample {
    Vec4 x, u;
    Tetrad e;
  };
  WorldlineEvent interpolate(std::size_t i, double s) const;  // s in [0,1] within step i
  // The event and frame `dtau` of proper time after sample `from` (at proper
  // time `tau`), integrated; throws ObserverError if the curve cannot get there.
  WorldlineEvent transported(const Sample& from, double dtau, double tau) const;

  Spacetime spacetime_;  // Minkowski unless set
  std::vector<Sample> samples_;
  double dtau_ = 0.0, duration_ = 0.0;
  // Uniform in trace coordinate time from start_time(), step dt_: the
  // centre, dx/dt, the 4-velocity and du/dt (geodesic equation).
  struct TimeSample {
    Vec4 x, dxdt, u, dudt;
  };
  std::vector<TimeSample> by_time_;
  std::vector<RestSpaceSpan> spans_;  // per coordinate-time sample: how its rest space lies
  double dt_ = 0.0;
  double top_speed_ = 0.0;
  // Per chunk of kChunk coordinate-time samples: spatial bounds, for the
  // spacetime tube.
  static constexpr std::size_t kChunk = 16;
  std::vector<std::array<Vec3, 2>> chunk_bounds_;
  // ... and the interpolant's top coordinate acceleration |d2x/dt2|.
  std::vector<double> chunk_acceleration_;
};

}  // namespace lc
