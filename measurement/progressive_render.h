#pragma once
// Rendering a progressive technique (one whose pass reports progress, such as the reference) until
// its result is complete: what `render`, `eval` and the reference frames of `eval` and `calibrate`
// do before they read a mask. A technique that reports no progress is complete after one frame.
//
//   auto done = render_until_complete(session, 1000, [](const exec::PassProgress& p) { print(p); });
#include <functional>

#include "exec/pass_progress.h"
#include "technique/technique_session.h"
#include "util/error.h"

namespace penumbra::measurement {

// Renders frames until session.progress() is complete, at most `max_frames`; `on_tenth` sees the
// progress whenever it passes another tenth of the total. An error (internal) when the limit is
// reached first.
Status render_until_complete(technique::TechniqueSession& session, int max_frames,
                             const std::function<void(const exec::PassProgress&)>& on_tenth = {});

// "raster: 412 / 1024 shadow maps (40%)", "raytraced: complete, 921600 rays".
std::string progress_text(const exec::PassProgress& progress);

}  // namespace penumbra::measurement
