#include "script/shot.hpp"

#include <algorithm>
#include <iterator>
#include <string_view>

#include <fmt/format.h>

#include "camera/delivery.hpp"
#include "lua/table_reader.hpp"
#include "scene/delivered_sky.hpp"
#include "scene/scene_skies.hpp"
#include "scene/frame_specs.hpp"
#include "scene/scene_spec.hpp"
#include "script/engine_api.hpp"
#include "script/scene_reader.hpp"
#include "scene/still_key.hpp"
#include "script/script_paths.hpp"

namespace lc {

namespace {

// Bounds of scene_fields' walk: how deep into nested tables, and how many
// fields in all (a scene that shares one table many times over could make
// the walk explode; then the comparison is skipped).
constexpr int kMaxFieldDepth = 8;
constexpr std::size_t kMaxFields = 100000;

// Fields of a scene that are the frame's alone: an instant's are not used,
// so they may be absent there.
constexpr std::string_view kFrameOnlyFields[] = {"exposure", "shutter"};

// Appends to `out` the path ("camera.yaw", "objects[2].position.r") of
// every field of the table at the stack top and of the tables in it (keys
// "__..." are the engine's tags and skipped). `walking` holds the tables
// being walked, so a table holding itself ends the walk there. Raw access;
// lua_next's order does not matter, the caller sorts. Returns false once
// more than kMaxFields were found.
bool collect_fields(lua_State* L, const std::string& prefix, int depth, std::vector<const void*>& walking,
                    std::vector<std::string>& out) {
  if (depth > kMaxFieldDepth ||
      std::find(walking.begin(), walking.end(), lua_topointer(L, -1)) != walking.end())
    return true;
  walking.push_back(lua_topointer(L, -1));
  bool within = true;
  lua_pushnil(L);
  while (within && lua_next(L, -2) != 0) {
    std::string path;
    if (lua_type(L, -2) == LUA_TSTRING) {
      std::size_t n = 0;
      const char* p = lua_tolstring(L, -2, &n);
      const std::string_view key(p, n);
      if (!key.starts_with("__")) path = prefix.empty() ? std::string(key) : fmt::format("{}.{}", prefix, key);
    } else if (lua_type(L, -2) == LUA_TNUMBER) {
      path = fmt::format("{}[{}]", prefix, lua_tonumber(L, -2));
    }
    if (!path.empty()) {
      if (lua_istable(L, -1)) within = collect_fields(L, path, depth + 1, walking, out);
      out.push_back(std::move(path));
      within = within && out.size() <= kMaxFields;
    }
    lua_pop(L, 1);
  }
  if (!within) lua_pop(L, 1);  // the key lua_next left
  walking.pop_back();
  return within;
}

// The sorted paths of the fields of the scene table at the stack top (see
// collect_fields), or nullopt if it has too many to compare.
std::optional<std::vector<std::string>> scene_fields(lua_State* L) {
  std::vector<const void*> walking;
  std::vector<std::string> out;
  if (!collect_fields(L, "", 0, walking, out)) return std::nullopt;
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

Shot::Shot(const std::filesystem::path& file, lua::SandboxLimits limits) : file_(file), limits_(std::move(limits)) {
  unused_.emplace(load(info_));
}

Shot::Loaded Shot::load(ShotInfo& info) {
  Loaded out{lua::Sandbox(require_dirs_for(file_), limits_)};
  out.sandbox.mount_modules(kShotsModulePrefix, shots_dir());
  install_engine_api(out.sandbox, &memo_);
  out.sandbox.run_file(file_, 1);
  lua_State* L = out.sandbox.state();
  if (!lua_istable(L, -1))
    throw lua::FieldError(fmt::format("{}: the script must return a shot table, got {}", file_.string(),
                                      luaL_typename(L, -1)));
  {
    lua::TableReader t(L, -1, file_.string());
    // Known before the other fields are read: a misspelt 'frames' must not
    // be taken for a misspelling of 'frame'.
    t.mark_known({"frame", "description"});
    info = read_shot_info(t);
    t.push_field("frame");
    if (!lua_isfunction(L, -1))
      throw lua::FieldError(fmt::format("{}: field 'frame' must be a function(i) returning the scene of frame i, got {}",
                                        file_.string(), luaL_typename(L, -1)));
    out.frame_ref = luaL_ref(L, LUA_REGISTRYINDEX);
    t.finish();
  }
  lua_pop(L, 1);
  note_loaded_files(out.sandbox);
  return out;
}

void Shot::note_loaded_files(const lua::Sandbox& sandbox) {
  for (const auto& p : sandbox.loaded_files())
    if (std::find(loaded_files_.begin(), loaded_files_.end(), p) == loaded_files_.end()) loaded_files_.push_back(p);
}

SceneSpec Shot::frame(int i) { return frame(i, nullptr); }

SceneSpec Shot::frame(int i, FieldPaths* fields) {
  const std::string ctx = fmt::format("{}: frame {}", file_.string(), i);
  if (i < 0 || i >= info_.frames)
    throw lua::FieldError(fmt::format("{}: no such frame (the shot has frames 0 to {})", ctx, info_.frames - 1));
  return evaluate(i, ctx, fields);
}

namespace {

// How the skies of `at` differ in kind from the frame's, each end's (the
// star stage draws each instant's point stars: a sky of another kind is a
// cut), or empty where they do not.
std::string sky_cut(const SceneSpec& frame, const SceneSpec& at) {
  std::vector<std::pair<std::string, std::string_view>> a, b;  // (end, kind)
  for_each_sky(frame, [&](std::string_view end, const SkySpec& s) { a.emplace_back(end, SkyRegistry::name(s)); });
  for_each_sky(at, [&](std::string_view end, const SkySpec& s) { b.emplace_back(end, SkyRegistry::name(s)); });
  if (a == b) return {};
  const auto list = [](const auto& skies) {
    std::string out;
    for (const auto& [end, kind] : skies)
      out += fmt::format("{}lc.{}{}", out.empty() ? "" : ", ", kind, end.empty() ? "" : fmt::format(" at {}", end));
    return out;
  };
  return fmt::format("the sky is {} at the frame but {}", list(a), list(b));
}

}  // namespace

FrameSpecs Shot::frame_specs(int i) {
  FrameSpecs out;
  FieldPaths frame_fields;
  out.frame = frame(i, &frame_fields);
  out.shutter = frame_shutter(info_.shot_shutter(), out.frame.shutter, shutter_override_);
  if (out.shutter.closed()) return out;
  const std::string frame_key = scene_key(out.frame);
  bool changes = false;
  for (const double t : out.shutter.instants()) {
    const double at = std::clamp(i + t, 0.0, static_cast<double>(info_.frames - 1));
    std::optional<lua::FieldError> lost;
    SceneSpec s = at == i ? out.frame : evaluate_instant(i, at, frame_fields, &lost);
    if (s.spacetime.index() != out.frame.spacetime.index())
      throw std::invalid_argument(fmt::format(
          "{}: frame {}: the spacetime is {} at the frame but {} at {:g}, within its shutter; a shutter cannot be "
          "open across a change of spacetime: close it for this frame (its `shutter = 0`)",
          file_.string(), i, spacetime_name(out.frame.spacetime), spacetime_name(s.spacetime), at));
    // The star stage draws each instant's point stars: a sky of another
    // kind within the shutter is a cut, too.
    if (const std::string cut = sky_cut(out.frame, s); !cut.empty())
      throw std::invalid_argument(fmt::format(
          "{}: frame {}: {} at {:g}, within its shutter; a shutter cannot be open across a change of sky: close it "
          "for this frame (its `shutter = 0`)",
          file_.string(), i, cut, at));
    // Each sample takes one instant's camera: a cut between cameras mixes
    // their pictures pixel by pixel.
    if (const auto cut = camera_cut(out.frame.camera, s.camera))
      throw std::invalid_argument(fmt::format(
          "{}: frame {}: the camera is {} at the frame but {} at {:g}, within its shutter; a shutter cannot be open "
          "across a change of camera kind, stereo layout or projection: close it for this frame (its `shutter = 0`)",
          file_.string(), i, cut->at_frame, cut->at_instant, at));
    if (lost) throw *lost;
    changes = changes || scene_key(s) != frame_key;
    out.times.push_back(t);
    out.instants.push_back(std::move(s));
  }
  if (!changes) {
    out.times.clear();
    out.instants.clear();
  }
  return out;
}

SceneSpec Shot::evaluate_instant(int i, double at, const FieldPaths& frame_fields,
                                 std::optional<lua::FieldError>* lost) {
  const std::string ctx = fmt::format("{}: frame {} at {:g}", file_.string(), i, at);
  const std::string hint = fmt::format(
      " (frame {}'s shutter is open: frame(i) is also called at fractional i, the instants of its shutter; a script "
      "that only knows whole frames can close it with `shutter = 0`: docs/motion_blur.md)",
      i);
  try {
    FieldPaths fields;
    SceneSpec s = evaluate(at, ctx, &fields);
    // A field set at the frame and absent at an instant would take its
    // default there without a word: most often a table indexed by i.
    if (frame_fields && fields) {
      std::vector<std::string> missing;
      std::set_difference(frame_fields->begin(), frame_fields->end(), fields->begin(), fields->end(),
                          std::back_inserter(missing));
      std::erase_if(missing, [](const std::string& f) {
        return std::find(std::begin(kFrameOnlyFields), std::end(kFrameOnlyFields), f) != std::end(kFrameOnlyFields);
      });
      if (!missing.empty())
        *lost = lua::FieldError(fmt::format(
            "{}: field '{}' is set at frame {} but not at {:g}: a table indexed by a fractional i gives nil (index "
            "by whole frames, math.floor(i), or interpolate between them), or the field appears or disappears "
            "within the shutter, a cut{}",
            ctx, missing.front(), i, at, hint));
    }
    return s;
  } catch (const lua::FieldError& e) {
    throw lua::FieldError(std::string(e.what()) + hint);
  } catch (const lua::ScriptError& e) {
    throw lua::ScriptError(std::string(e.what()) + hint);
  }
}

SceneSpec Shot::evaluate(double at, const std::string& ctx, FieldPaths* fields) {
  ShotInfo unused_info;
  Loaded fresh = unused_ ? std::move(*unused_) : load(unused_info);
  unused_.reset();
  lua_State* L = fresh.sandbox.state();
  lua_rawgeti(L, LUA_REGISTRYINDEX, fresh.frame_ref);
  lua_pushnumber(L, at);
  try {
    fresh.sandbox.call(1, 1);
    note_loaded_files(fresh.sandbox);  // modules required inside frame()
  } catch (const lua::ScriptError& e) {
    // The script's line alone does not say which of its frames failed.
    throw lua::ScriptError(fmt::format("{}: {}", ctx, e.what()));
  }
  if (!lua_istable(L, -1)) {
    const std::string got = luaL_typename(L, -1);
    lua_pop(L, 1);
    throw lua::FieldError(fmt::format("{}: frame(i) must return a scene table, got {}", ctx, got));
  }
  SceneSpec fs;
  try {
    lua::TableReader t(L, -1, ctx);
    fs = read_scene_spec(t);
    if (fields != nullptr) *fields = scene_fields(L);
    lua_pop(L, 1);
  } catch (...) {
    lua_pop(L, 1);
    throw;
  }
  fs.camera = delivered(fs.camera, delivery_);
  try {
    fs.sky = delivered_sky(fs.sky, delivery_.sky);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: {}", ctx, e.what()));
  }
  return fs;
}

std::vector<std::filesystem::path> Shot::loaded_files() const { return loaded_files_; }

std::vector<std::filesystem::path> Shot::asset_dirs() const {
  std::filesystem::path own = file_.parent_path();
  if (own.empty()) own = ".";
  return {own, shots_dir()};
}

}  // namespace lc
