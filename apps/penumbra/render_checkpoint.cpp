#include "apps/penumbra/render_checkpoint.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "job/option_table.h"

namespace penumbra {

namespace {

std::string file_hash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    uint64_t h = 1469598103934665603ull;  // FNV-1a
    char buf[1 << 16];
    while (in.read(buf, sizeof buf) || in.gcount() > 0) {
        for (std::streamsize i = 0; i < in.gcount(); ++i)
            h = (h ^ static_cast<unsigned char>(buf[i])) * 1099511628211ull;
        if (!in) break;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

}  // namespace

std::string render_fingerprint(const BatchJob& job, const SceneSetup& setup,
                               const RenderOptions& ropt) {
    std::ostringstream f;
    // What the options resolved to, beside every option that decides pixels as declared
    // (job/option_table.cpp): a checkpoint resumes only the same render.
    f.precision(17);
    f << "penumbra-checkpoint-v2 scene=" << job.scene << " bytes=" << file_hash(job.scene)
      << " size=" << setup.width << "x" << setup.height << " rows=" << ropt.row_begin << "-"
      << ropt.row_end << " shutter=" << setup.scene.shutter_open << "-"
      << setup.scene.shutter_close << " time=" << ropt.time << " "
      << pixel_options_text(job.options);
    // A view's camera comes from the bounds or a file, not from the options' text alone.
    if (job.view >= 0) {
        const Mat4& m = setup.camera_desc.to_world.matrix();
        f << " view=" << job.view << " camera=";
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) f << m.m[r][c] << (r == 3 && c == 3 ? "" : ",");
        f << " yfov=" << setup.camera_desc.yfov;
    }
    return f.str();
}

}  // namespace penumbra
