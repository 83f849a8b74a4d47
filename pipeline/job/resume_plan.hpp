#pragma once
// Which frames of a render still need rendering, given what the frame store
// already holds (frame_store.hpp says what is trusted), and the refusal when
// finished frames were made from other settings or inputs.

#include <string>
#include <vector>

#include "store/frame_store.hpp"
#include "job/shot_survey.hpp"

namespace lc::farm {

struct ResumePlan {
  std::vector<int> todo;     // in the order asked for
  std::vector<int> done;     // finished already: skipped
  std::vector<int> damaged;  // journalled, but files missing or changed: rendered again
  std::vector<int> stale;    // finished from other settings or inputs: rendered again (--force)
};

// Sorts `frames` into the plan.  Without `force`, stale frames make it throw
// std::runtime_error explaining what differs (settings, or which input
// files changed) and how to proceed.
ResumePlan plan_resume(const FrameStore& store, const ShotSurvey& survey, const FrameSettings& settings,
                       const std::vector<int>& frames, bool force, const std::string& shot_name);

}  // namespace lc::farm
