#pragma once
// SceneSpec (plain data from the script) -> Scene (ready to trace): builds
// the spacetime in the chart rays are traced in, the observer's event and
// tetrad, the camera, the sky and the objects; worldlines and textures come
// once per shot from ShotResources.

#include <filesystem>

#include "render/scene.hpp"
#include "assets/shot_resources.hpp"
#include "scene/frame_specs.hpp"
#include "scene/scene_spec.hpp"

namespace lc {


// Throws std::invalid_argument for a scene that cannot exist (an observer
// inside a horizon or a static one in the ergoregion, a worldline from a
// different spacetime, ...).
// `window`: the image is that window of the whole frame (render --region).
Scene build_scene(const SceneSpec& fs, int width, int height, ShotResources& resources,
                  const RayOptions& rays = RayOptions{}, const ImageWindow& window = {});

// The frame's scene with, where its shutter is open and the scene changes
// within it, the scene at each instant (SceneIn::instants).  Throws as
// build_scene does, naming the instant ("at +0.125 of the frame").
Scene build_scene(const FrameSpecs& specs, int width, int height, ShotResources& resources,
                  const RayOptions& rays = RayOptions{}, const ImageWindow& window = {});

// build_scene for frame `frame` of the shot in `shot_file`: what render,
// trace and inspect all do, errors naming the file and the frame.
Scene build_scene(const SceneSpec& fs, const std::filesystem::path& shot_file, int frame, int width, int height,
                        ShotResources& resources, const RayOptions& rays = RayOptions{},
                        const ImageWindow& window = {});
Scene build_scene(const FrameSpecs& specs, const std::filesystem::path& shot_file, int frame, int width, int height,
                  ShotResources& resources, const RayOptions& rays = RayOptions{}, const ImageWindow& window = {});

}  // namespace lc
