#pragma once
// A shot script: the frame-independent settings, and frame(i) -> SceneSpec
// by calling the script's frame function.
//
// A frame's scene depends on the shot's files and i alone: each frame(i)
// runs the script afresh in a sandbox of its own, so nothing a script keeps
// in a global, an upvalue or a table survives from one frame to the next,
// and a frame renders the same alone, resumed, in any order and on any rank
// (docs/shots.md, "Frames are independent").  The sandbox that read the
// settings serves the first frame asked for.  Not thread-safe; every thread
// or rank that needs scenes may share one under a lock or load its own.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "camera/delivery_camera.hpp"
#include "lua/sandbox.hpp"
#include "lua/table_reader.hpp"
#include "scene/shot_info.hpp"
#include "scene/shutter.hpp"
#include "script/engine_api.hpp"

namespace lc {

// Declared only: they hold every registry's spec, and what loads a shot
// for its settings, files or delivery need none (docs/architecture.md,
// "What a new kind rebuilds"); what takes its frames includes them.
struct SceneSpec;   // scene/scene_spec.hpp
struct FrameSpecs;  // scene/frame_specs.hpp

class Shot {
 public:
  // Runs the script (sandboxed) and reads the shot table it returns.  Throws
  // lua::ScriptError / lua::FieldError naming the file and line or field.
  explicit Shot(const std::filesystem::path& file, lua::SandboxLimits limits = {});

  const ShotInfo& info() const { return info_; }
  const std::filesystem::path& file() const { return file_; }

  // The scene of frame i (0-based, < info().frames).  Errors name the file,
  // the frame and the field.  Its camera is the one the shot is delivered
  // through and its sky the one it is delivered under (camera/delivery.hpp):
  // its own unless set_delivery said other.
  SceneSpec frame(int i);

  // Frame i with its shutter (scene/frame_specs.hpp): where the shutter is
  // open, frame(i + t) at each instant t of it, clamped to the shot's
  // frames [0, frames-1] (the shot holds still before its first frame and
  // after its last: a script need only make sense on its own frames).
  // Errors name the fractional frame the script failed at.  Throws
  // std::invalid_argument where the spacetime's or the sky's kind, or the
  // camera's kind, stereo layout or projection, changes within the shutter
  // (a cut: the frame's shutter must be closed).
  FrameSpecs frame_specs(int i);

  // The command line's shutter over the shot's and its frames' (render
  // --shutter ...).
  void set_shutter(const ShutterOverride& over) { shutter_override_ = over; }
  const ShutterOverride& shutter_override() const { return shutter_override_; }

  // Every frame from now on through `to`'s camera and under its sky
  // (render --camera, --sky).
  void set_delivery(const Delivery& to) { delivery_ = to; }
  const Delivery& delivery() const { return delivery_; }

  // The script and every module it required, in any frame evaluated so far
  // (for hashing a shot's inputs).
  std::vector<std::filesystem::path> loaded_files() const;
  // Where the shot's assets (sky images) are looked for: its own folder,
  // then the project's shots/ folder.
  std::vector<std::filesystem::path> asset_dirs() const;

 private:
  // The sorted paths of the fields a frame's scene table sets
  // ("camera.yaw"), to compare an instant's with its frame's; nullopt for
  // a scene too large to compare.
  using FieldPaths = std::optional<std::vector<std::string>>;
  // frame(i), also noting the paths of its fields if `fields` is given.
  SceneSpec frame(int i, FieldPaths* fields);
  // A sandbox that has run the script, and its frame function.
  struct Loaded {
    lua::Sandbox sandbox;
    int frame_ref = LUA_NOREF;  // registry reference to the frame function
  };
  // Runs the script in a new sandbox and reads the shot table it returns
  // into `info`; throws as the constructor does.
  Loaded load(ShotInfo& info);
  // The script's frame(at) (at: a frame number, fractional at a shutter's
  // instants), its errors prefixed with `ctx`; the paths of its scene's
  // fields into `fields` if given.
  SceneSpec evaluate(double at, const std::string& ctx, FieldPaths* fields = nullptr);
  // evaluate at `at`, an instant of frame i's shutter, its errors saying
  // so. Where a field of the frame's scene (`frame_fields`) is absent at
  // the instant, `*lost` is the lua::FieldError to throw once the caller
  // has looked for a cut between the two scenes, whose message says more.
  SceneSpec evaluate_instant(int i, double at, const FieldPaths& frame_fields, std::optional<lua::FieldError>* lost);
  void note_loaded_files(const lua::Sandbox& sandbox);

  std::filesystem::path file_;
  lua::SandboxLimits limits_;
  EngineMemo memo_;  // before the sandboxes, which point at it
  ShotInfo info_;
  std::optional<Loaded> unused_;  // the constructor's sandbox, until a frame uses it
  std::vector<std::filesystem::path> loaded_files_;
  Delivery delivery_{};
  ShutterOverride shutter_override_{};
};

}  // namespace lc
