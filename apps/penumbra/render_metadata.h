// The EXR header fields that say how one image of `render` was made: the program, the
// scene, the options in effect, the samples rendered, the lens and the timeline. The
// render's time only with --timing-metadata: by default the same command writes a
// bitwise identical file.
#pragma once

#include <string>

#include "apps/penumbra/render_command.h"
#include "apps/penumbra/scene_setup.h"
#include "integrators/render.h"
#include "io/image/image_writer.h"

namespace penumbra {

Metadata render_metadata(const RenderCommandOptions& o, const std::string& scene,
                         const SceneSetup& setup, const RenderStats& stats);

}  // namespace penumbra
