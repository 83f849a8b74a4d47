#include "stages/store_sink.hpp"


namespace lc::farm {

StoreSink::StoreSink(FrameStore& store, const ShotSurvey& survey, const ShotInfo& shot, const RenderSettings& rs,
                     const FrameSettings& settings, std::vector<int> preview_rows,
                     std::vector<std::filesystem::path> asset_dirs, int star_threads, EventLog* events)
    : store_(store), survey_(survey), look_(shot.look()),
      settings_(settings), preview_rows_(std::move(preview_rows)),
      finisher_(shot.name, shot.fps, rs, std::move(asset_dirs), star_threads), events_(events) {}

Look StoreSink::frame_look(const FrameFacts& facts) const {
  Look look = look_;
  if (facts.exposure) look.exposure = *facts.exposure;
  return look;
}

void StoreSink::store(const CompletedFrame& cf) {
  if (cf.pass == Pass::preview) {
    // Previews show no point stars: their missing rows are copies, and
    // copied rays make no patches of sky.
    FrameImage preview{cf.image.width, cf.image.height, cf.image.rgb, cf.image.layers, {}, cf.image.alpha};
    store_.write_preview(cf.frame, std::move(preview), preview_rows_, frame_look(survey_.frames.at(cf.frame)));
    return;
  }
  const FrameFacts& facts = survey_.frames.at(cf.frame);
  const FinishedFrame f = finisher_.finish(cf, facts);
  if (f.starred) {
    std::lock_guard lock(star_mutex_);
    star_seconds_ += f.cost.star_seconds;
    star_wall_seconds_ += f.star_wall_seconds;
  }
  const FrameCost& cost = f.cost;
  store_.write_frame(cf.frame, f.image(cf), f.metadata, settings_, facts.inputs, facts.parts, cost, frame_look(facts),
                     cf.makers, cf.dispatched);
  if (events_) events_->frame_stored(cf.frame, cost.core_seconds + cost.star_seconds, cost.rays);
}

double StoreSink::star_seconds() const {
  std::lock_guard lock(star_mutex_);
  return star_seconds_;
}

double StoreSink::star_wall_seconds() const {
  std::lock_guard lock(star_mutex_);
  return star_wall_seconds_;
}

}  // namespace lc::farm
