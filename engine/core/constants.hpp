#pragma once
// Every numerical constant and default the engine uses lives here, so that a
// tolerance or a threshold is changed in one place and cited from one place.

#include <cstddef>
#include <numbers>

namespace lc {

inline constexpr double pi = std::numbers::pi;
inline constexpr double two_pi = 2.0 * std::numbers::pi;
inline constexpr double degree = std::numbers::pi / 180.0;  // radians per degree

// Physical constants in SI (CODATA 2018; h, c, k exact by the 2019 SI), for
// blackbody light (light/blackbody.hpp) and a disk's temperature from its
// accretion rate (light/novikov_thorne.hpp).
inline constexpr double planck_h = 6.62607015e-34;             // J s
inline constexpr double speed_of_light = 299792458.0;          // m / s
inline constexpr double boltzmann_k = 1.380649e-23;            // J / K
inline constexpr double stefan_boltzmann = 5.670374419e-8;     // W m^-2 K^-4
inline constexpr double gravitational_constant = 6.67430e-11;  // m^3 kg^-1 s^-2
// The Sun's mass from IAU 2015 Resolution B3's nominal GM (1.3271244e20
// m^3 s^-2) over G; a Julian year.
inline constexpr double solar_mass = 1.3271244e20 / gravitational_constant;  // kg
inline constexpr double julian_year = 365.25 * 86400.0;                       // s
// Luminous efficacy of the photopic curve y-bar (lm / W; CIE): luminance in
// cd m^-2 is this times the y-bar-weighted radiance in W sr^-1 m^-2.
inline constexpr double luminous_efficacy = 683.0;

// Null rays are stopped at this Boyer–Lindquist (or Cartesian) radius when
// moving outwards: beyond the outermost photon orbit no ray turns back, so the
// remaining bending only changes the escape direction (by about 2M/r).
inline constexpr double default_escape_radius = 1000.0;
// Where the far field is a known monopole (the dihole's isotropic
// coordinates, flat space; spacetime/weak_field_tail.hpp), rays escape
// earlier: beyond the objects, once the multipoles beyond the monopole
// (the dihole's dipole |m1 - m2| d / r^2, or for equal holes its quadrupole
// M d^2 / r^3) bend light by less than this, in radians.
// A pixel of the paper's dihole shots spans ~2e-4 rad.
inline constexpr double far_field_bending = 1e-6;

// The extreme Reissner–Nordström holes (the dihole, Majumdar–Papapetrou)
// are coordinate points: a ray is taken as captured once
// U = 1 + Σ m_i/ρ_i exceeds this bound.  U > 11 forces ρ_i < 0.1 N m_i for
// the dominant of N holes, inside its photon sphere (ρ ≈ m) for N < 10,
// from where no ray comes back out; holes far apart each have their own
// capture sphere of radius ≈ m_i / 10.
inline constexpr double extreme_hole_capture_potential = 11.0;

// Kerr capture: inside the prograde equatorial photon orbit no ray (and no
// timelike geodesic) has a radial turning point, so an ingoing one is lost.
// Rays are stopped this fraction of the way from the prograde photon orbit
// down to the outer horizon, so they never crawl towards it in ingoing
// Kerr–Schild time (where t diverges logarithmically).
inline constexpr double kerr_capture_fraction = 0.5;

// Kottler's outer stop rule (spacetime/kottler.hpp): a ray moving outwards
// ends where F = -g_tt of the static chart falls to this, just below the
// cosmological horizon (a static observer there is redshifted 30-fold),
// and is carried straight to it.  Closer, the integration follows the
// chart's time diverging (logarithmically) for no change in direction.
inline constexpr double kottler_stop_lapse2 = 1e-3;

// Default step-control tolerance (relative and absolute) of the production
// Dormand–Prince integrator, chosen by measured image error
// (docs/performance.md, change 6): at 5e-8 no pixel of the benchmark shots
// changes its hit kind against a 1e-13 reference and the 99th percentile of
// the disk-hit radius error is 7e-6 M (issue 6 asks for 1e-5).  Work that
// needs more — conserving constants of motion to 1e-8 on rays that wind
// round the photon sphere, reference renders — sets its own
// (conservation_ray_tolerance, `bench --reference-tolerance`).
inline constexpr double default_ray_tolerance = 5e-8;
// What keeps E, L_z and Q of Kerr rays within 1e-8 along rays that wind
// round the photon sphere in the Kerr–Schild integrator (1e-9 gave 3e-8).
inline constexpr double conservation_ray_tolerance = 1e-10;

// Adaptive supersampling: a pixel whose first sample agrees with its row
// neighbours' in hit kind and in every colour channel to within this, after
// the sRGB transfer curve (about one 8-bit step: compared in linear RGB the
// dark sky, where the curve is steep, hid steps of several codes), is not
// refined.  docs/performance.md, changes 9 and 19, measure what it saves
// and costs against other thresholds.
inline constexpr double adaptive_sample_threshold = 1.0 / 256.0;

// A ray moving outwards beyond every object and photon orbit of its scene
// (RayOptions::free_radius) can meet nothing more: the rest of its path only
// aims the sky lookup, where an error of 1e-6 rad is a fiftieth of a pixel
// of the paper's narrowest view.  Its tolerances are multiplied by this.
// docs/performance.md, change 11.
inline constexpr double free_flight_relaxation = 100.0;

// An observer whose |sin(theta)| is below this is on the spin axis for the
// Boyer–Lindquist–Mino rays: they leave along one meridian with p_phi = 0.
// theta = 180 deg is pi rounded, whose sine is 1.2e-16, not 0; and rays
// that start with p_phi ~ r sin(theta) != 0 turn at sin(theta) ~ 1e-9 and
// below in steps too small to take (they gave up, measured).  Starting
// them on the axis moves them by r |sin(theta)|: 3e-5 M at r = 30.
inline constexpr double spin_axis_sine = 1e-6;

// What a shot may ask the engine to hold in memory (docs/shots.md, "Limits").
// A process keeps the worldlines, sky images and star fields of the frames
// it works on within shot_resource_budget, releasing those no scene uses,
// least recently used first.  One worldline is held at ~9.5 KB per M of
// proper time (~13.5 KB while it is integrated: 0.05 M samples with their
// tetrads, and a coordinate-time table of twice as many), so the longest
// costs ~270 MB; a star field or sky image 12 bytes a pixel (linear float
// RGB), at most ~400 MB and 1.5 GiB.
inline constexpr std::size_t shot_resource_budget = std::size_t{4} << 30;
inline constexpr double max_worldline_duration = 20000.0;
inline constexpr int max_star_field_width = 8192;
inline constexpr long max_sky_image_pixels = 16384L * 8192L;

// The longest shot name: it names the output files (<name>.<NNNN>.exr and
// the journal), and file names have at most 255 bytes.
inline constexpr std::size_t max_shot_name_length = 128;
// The most objects a scene may hold: every ray is tested against each, and
// the scene is copied out of Lua (a script can list one sphere a million
// times in a few MiB of Lua memory, which would take GiBs here).
inline constexpr std::size_t max_scene_objects = 1000;
// The most instants a shutter may be cut into (scene/shutter.hpp): each is
// an evaluation of the shot, a scene held while the frame renders and,
// under a sky of point stars, a ray per pixel for the star stage.
inline constexpr int max_time_samples = 64;

// How far from the origin an observer may be (M): a ray from farther away
// starts at a coordinate time and radius so large that double precision
// cannot resolve the steps near the hole (measured: Kerr renders from 1e10 M,
// every ray gives up from 3e10 M).  A distant view: the observer at 1e9 M
// with a narrow field of view (docs/shots.md).
inline constexpr double max_observer_distance = 1e10;

// Default safety bound on the number of accepted steps of one ray.
inline constexpr long default_max_steps = 100000;

}  // namespace lc
