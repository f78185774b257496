// Render checkpoints: a film's raw accumulators and the samples per pixel done, so a
// stopped render continues exactly where it was (rendering [0,k) then [k,n) equals
// [0,n)), and a fingerprint of the scene and options so a changed job starts afresh.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/film/film.h"

namespace penumbra {

struct CheckpointState {
    std::string fingerprint;  // what was rendered: scene, options, rows (see render_command)
    uint32_t spp = 0;         // samples [0, spp) of every pixel are in the film
    uint64_t rays = 0;        // totals so far, for the statistics of the finished image
    double seconds = 0;
};

// The checkpoint that belongs to an output image: OUTPUT.ckpt beside it.
std::string checkpoint_path(const std::string& output);

// Writes every buffer of film (Film::buffers) and state, atomically: a kill at any
// moment leaves the previous checkpoint or the new one. Throws SceneError naming path.
void write_checkpoint(const std::string& path, const Film& film, const CheckpointState& state);

// Fills film (already sized, with the AOVs of the render) from path when the file's
// fingerprint equals `fingerprint` and its buffers match the film's in name and size.
// Otherwise returns nothing, says why in *why (missing, stale, damaged) and leaves film
// untouched.
std::optional<CheckpointState> read_checkpoint(const std::string& path,
                                               const std::string& fingerprint, Film& film,
                                               std::string* why = nullptr);

}  // namespace penumbra
