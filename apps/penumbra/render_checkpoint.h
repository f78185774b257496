// What makes a checkpoint valid for a render: a fingerprint of everything that decides
// the pixels (the scene file's bytes, the image options, the rows), so a changed job
// starts afresh instead of continuing a stale film.
#pragma once

#include <string>

#include "apps/penumbra/batch.h"
#include "apps/penumbra/scene_setup.h"
#include "integrators/render.h"

namespace penumbra {

// A readable, canonical string of the options that decide the pixels, plus a hash of
// the scene file. Not covered: external buffers and textures edited in place (their
// names are in the scene file, their bytes are not hashed; docs/farm.md).
std::string render_fingerprint(const BatchJob& job, const SceneSetup& setup,
                               const RenderOptions& ropt);

}  // namespace penumbra
