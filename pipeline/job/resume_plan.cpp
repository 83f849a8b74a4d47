#include "job/resume_plan.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "store/frame_list.hpp"

namespace lc::farm {

namespace {

// Why stale frames differ: settings per group, and the input files whose
// recorded hash differs from today's.
std::string explain_stale(const FrameStore& store, const ShotSurvey& survey, const FrameSettings& settings,
                          const std::vector<int>& stale) {
  std::vector<std::string> reasons;
  // Grouped by their settings' words beside this render's (each group's
  // first frame stands for it).
  std::map<std::string, std::pair<FrameSettings, std::vector<int>>> by_settings;
  std::vector<int> by_inputs;
  for (int f : stale) {
    const JournalFrame& jf = store.journal().frames.at(f);
    if (!(jf.settings == settings)) {
      auto& group = by_settings[jf.settings.describe(settings)];
      group.first = jf.settings;
      group.second.push_back(f);
    } else {
      by_inputs.push_back(f);
    }
  }
  for (const auto& [desc, group] : by_settings)
    reasons.push_back(fmt::format("{} rendered at {}, this render asks for {}", frames_were(group.second), desc,
                                  settings.describe(group.first)));
  if (!by_inputs.empty()) {
    // A file the journal never recorded is one the frames did not read
    // (a catalogue or sky image now at another path).
    std::vector<std::string> changed, unread;
    for (const auto& [path, hash] : survey.files) {
      auto it = store.journal().inputs.find(path);
      if (it == store.journal().inputs.end()) unread.push_back(path);
      else if (it->second != hash) changed.push_back(path);
    }
    std::vector<std::string> what;
    if (!changed.empty()) what.push_back(fmt::format("other versions of: {}", fmt::join(changed, ", ")));
    if (!unread.empty())
      what.push_back(fmt::format("other files than this render reads: {} {} not among them", fmt::join(unread, ", "),
                                 unread.size() == 1 ? "was" : "were"));
    reasons.push_back(fmt::format(
        "{} rendered from {}", frames_were(by_inputs),
        what.empty() ? std::string("other inputs (the script, its modules, sky images or star catalogues)")
                     : fmt::format("{}", fmt::join(what, "; and from "))));
  }
  return fmt::format("{}", fmt::join(reasons, "; "));
}

}  // namespace

ResumePlan plan_resume(const FrameStore& store, const ShotSurvey& survey, const FrameSettings& settings,
                       const std::vector<int>& frames, bool force, const std::string& shot_name) {
  ResumePlan plan;
  for (int f : frames) {
    switch (store.state(f, settings, survey.frames.at(f).inputs)) {
      case FrameState::done:
        plan.done.push_back(f);
        break;
      case FrameState::todo:
        plan.todo.push_back(f);
        break;
      case FrameState::damaged:
        plan.damaged.push_back(f);
        plan.todo.push_back(f);
        break;
      case FrameState::stale:
        plan.stale.push_back(f);
        plan.todo.push_back(f);
        break;
    }
  }
  if (!plan.stale.empty() && !force)
    throw std::runtime_error(fmt::format(
        "--out {}: refusing to resume '{}': it holds finished frames made differently — {}. Rendering on would mix "
        "old and new frames; use another --out, or pass --force to render those frames again (frames that match "
        "are kept)",
        store.dir().string(), shot_name, explain_stale(store, survey, settings, plan.stale)));
  return plan;
}

}  // namespace lc::farm
