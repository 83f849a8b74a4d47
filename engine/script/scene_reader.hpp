#pragma once
// Script tables -> the plain-data SceneSpec (scene/scene_spec.hpp).  Each object kind
// has one reader, used twice: by its constructor (lc.disk{...} etc.), which
// validates the arguments where the script calls it so errors name that
// line, and by the frame reader, which converts the constructor's tagged
// table.  So every field is declared once.
//
// Positions and velocities depend on the spacetime (Boyer–Lindquist
// {r, theta, phi} for Kerr, {x, y, z} otherwise); readers given no spacetime
// (constructors) check only that one of the two forms is used.

#include "lua/table_reader.hpp"
#include "scene/scene_spec.hpp"

namespace lc {

// A position as the script gave it: polar (t, r, theta, phi; angles already
// in radians) or Cartesian (t, x, y, z).
struct ScriptPosition {
  bool polar = false;
  Vec4 coords{};
};

ScriptPosition read_position(lua::TableReader& t);
// The position in the spacetime's scene coordinates; throws FieldError when
// the form does not match the spacetime.
Vec4 resolve_position(const ScriptPosition& p, const Spacetime& st, const std::string& context);

// A table made by a constructor of the camera or sky registries.
CameraSpec read_camera(lua::TableReader& t);
SkySpec read_sky(lua::TableReader& t);
// The scene's `skies`: a sky for each far end of st by its name
// (SpacetimeEnd::name), checked against st's ends, in their order;
// scene_has_sky: whether the scene also gives `sky` (the first end's, then
// given twice).
std::vector<EndSky> read_end_skies(lua::TableReader& t, const Spacetime& st, bool scene_has_sky);
WorldlineSpec read_worldline(lua::TableReader& t);
// lc.light{...}.
LightParams read_light(lua::TableReader& t);
// A table made by a constructor of the object or observer registries:
// object (a sphere's) and observer positions resolve against `st` when given.
ObjectSpec read_object(lua::TableReader& t, const Spacetime* st);
ObserverSpec read_observer(lua::TableReader& t, const Spacetime* st);

// The table a shot's frame(i) returns.
SceneSpec read_scene_spec(lua::TableReader& t);

// Frame-independent fields of a shot table (name, frames, fps, width,
// height, supersample); the frame function is read by the caller.
ShotInfo read_shot_info(lua::TableReader& t);

}  // namespace lc
