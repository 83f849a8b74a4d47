#include "script/shot.hpp"

#include <fmt/format.h>

#include "lua/table_reader.hpp"
#include "script/engine_api.hpp"
#include "script/scene_reader.hpp"
#include "script/script_paths.hpp"

namespace lc {

Shot::Shot(const std::filesystem::path& file, lua::SandboxLimits limits)
    : file_(file), sandbox_(require_dirs_for(file), std::move(limits)) {
  install_engine_api(sandbox_);
  sandbox_.run_file(file_, 1);
  lua_State* L = sandbox_.state();
  if (!lua_istable(L, -1))
    throw lua::FieldError(fmt::format("{}: the script must return a shot table, got {}", file_.string(),
                                      luaL_typename(L, -1)));
  {
    lua::TableReader t(L, -1, file_.string());
    // Known before the other fields are read: a misspelt 'frames' must not
    // be taken for a misspelling of 'frame'.
    t.mark_known({"frame", "description"});
    info_ = read_shot_info(t);
    t.push_field("frame");
    if (!lua_isfunction(L, -1))
      throw lua::FieldError(fmt::format("{}: field 'frame' must be a function(i) returning the scene of frame i, got {}",
                                        file_.string(), luaL_typename(L, -1)));
    frame_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
    t.finish();
  }
  lua_pop(L, 1);
}

Shot::~Shot() {
  if (lua_State* L = sandbox_.state()) luaL_unref(L, LUA_REGISTRYINDEX, frame_ref_);
}

SceneSpec Shot::frame(int i) {
  lua_State* L = sandbox_.state();
  const std::string ctx = fmt::format("{}: frame {}", file_.string(), i);
  if (i < 0 || i >= info_.frames)
    throw lua::FieldError(fmt::format("{}: no such frame (the shot has frames 0 to {})", ctx, info_.frames - 1));
  lua_rawgeti(L, LUA_REGISTRYINDEX, frame_ref_);
  lua_pushinteger(L, i);
  try {
    sandbox_.call(1, 1);
  } catch (const lua::ScriptError& e) {
    // The script's line alone does not say which of its frames failed.
    throw lua::ScriptError(fmt::format("{}: {}", ctx, e.what()));
  }
  if (!lua_istable(L, -1)) {
    const std::string got = luaL_typename(L, -1);
    lua_pop(L, 1);
    throw lua::FieldError(fmt::format("{}: frame(i) must return a scene table, got {}", ctx, got));
  }
  try {
    lua::TableReader t(L, -1, ctx);
    SceneSpec fs = read_scene_spec(t);
    lua_pop(L, 1);
    return fs;
  } catch (...) {
    lua_pop(L, 1);
    throw;
  }
}

std::vector<std::filesystem::path> Shot::loaded_files() const { return sandbox_.loaded_files(); }

std::vector<std::filesystem::path> Shot::asset_dirs() const {
  std::filesystem::path own = file_.parent_path();
  if (own.empty()) own = ".";
  return {own, library_dir().parent_path() / "shots"};
}

}  // namespace lc
