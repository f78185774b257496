// The option table's declarations of where and when an image looks: views, the timeline
// and frames (option_table.cpp holds the rest).
#include <limits>

#include "job/option_builders.h"
#include "job/option_table_parts.h"
#include "job/view_list.h"

namespace penumbra {

using namespace option_builders;

// Many views of one scene: an orbit or a cameras file, one image each.
void add_view_options(std::vector<OptionDecl>& t) {
    OptionDecl views = path({"views", "views", "penumbra:views", kPixels, kRender,
                             "One image per view, all from one load of the scene: orbit:N (N "
                             "views evenly around the vertical axis, +Y, through the centre "
                             "of the scene's bounds) or a JSON file of cameras ([{\"position\": "
                             "[x,y,z], \"look_at\": [x,y,z], \"up\": [0,1,0], \"yfov\": "
                             "degrees} or {\"matrix\": 4x4 camera-to-world rows}, ...]); "
                             "writes transforms.json (NeRF convention) beside the images",
                             Header::WhenSet},
                            FIELD(views));
    views.keyword_prefix = "orbit:";
    views.set = [](RenderCommandOptions& o, const std::string& spec) {
        check_views_spec(spec);  // throws std::invalid_argument saying what is wrong
        o.views = spec;
    };
    t.push_back(views);
    t.push_back(number<float>({"orbit-elevation", "orbit_elevation", "", kPixels, kRender,
                               "--views orbit:N: degrees above the horizontal plane through "
                               "the scene's centre"},
                              FIELD(orbit.elevation), -89, 89));
    t.push_back(number<float>({"orbit-distance", "orbit_distance", "", kPixels, kRender,
                               "--views orbit:N: distance from the scene's centre (0: framed "
                               "as the default camera frames the scene's bounds)"},
                              FIELD(orbit.distance), 0, kInf));
    t.push_back(number<float>({"orbit-fov", "orbit_fov", "", kPixels, kRender,
                               "--views: vertical field of view in degrees, of the orbit and "
                               "of cameras-file views that give no yfov"},
                              FIELD(orbit.yfov), 0, 179, true));
    t.push_back(number<float>({"orbit-jitter", "orbit_jitter", "", kPixels, kRender,
                               "--views orbit:N: move each view's azimuth and elevation by a "
                               "random angle of up to this many degrees (from --orbit-seed)"},
                              FIELD(orbit.jitter), 0, 180));
    t.push_back(number<uint64_t>({"orbit-seed", "orbit_seed", "", kPixels, kRender,
                                  "--orbit-jitter's seed: the same seed gives the same cameras"},
                                 FIELD(orbit.seed), 0, kInf));
}

// The instant or interval of the animation the image exposes.
void add_timeline_options(std::vector<OptionDecl>& t) {
    t.push_back(timing(optional_number<double>(
        {"time", "time", "", kPixels, kImage,
         "Render the animation at this instant, in seconds: no motion blur (default 0)"},
        FIELD(timeline.time), -kInf, kInf)));
    t.push_back(timing(optional_number<double>(
        {"shutter-open", "shutter_open", "", kPixels, kImage,
         "Motion blur: the exposure opens at this animation time, in seconds (with "
         "--shutter-close)"},
        FIELD(timeline.shutter_open), -kInf, kInf)));
    t.push_back(timing(optional_number<double>(
        {"shutter-close", "shutter_close", "", kPixels, kImage,
         "Motion blur: the exposure closes at this animation time, in seconds"},
        FIELD(timeline.shutter_close), -kInf, kInf)));
    OptionDecl frame = timing(optional_number<int>(
        {"frame", "frame", "penumbra:frame", kPixels, kImage,
         "Render frame N: the shutter opens at N / fps", Header::WhenSet},
        FIELD(timeline.frame), 0, std::numeric_limits<int>::max()));
    frame.job_set = [](RenderCommandOptions& o, const std::string& n) { o.frames = n; };
    t.push_back(frame);
    t.push_back(number<double>({"fps", "fps", "", kPixels, kImage,
                                "Frames per second for --frame and --frames"},
                               FIELD(timeline.fps), 0, kInf, true));
    t.push_back(optional_number<double>(
        {"shutter", "shutter", "", kPixels, kImage,
         "Motion blur with --frame/--frames: the shutter stays open this fraction of a "
         "frame (0.5: a 180-degree shutter)"},
        FIELD(timeline.shutter), 0, 1));
}

// Image size, samples, threads, seed and what of the file to render.
void add_frame_options(std::vector<OptionDecl>& t) {
    t.push_back(number<int>({"width", "width", "", kPixels, kImage,
                             "Image width in pixels (default 640, or from --height and the "
                             "camera's aspect ratio)"},
                            FIELD(width), 1, 1 << 15));
    t.push_back(number<int>({"height", "height", "", kPixels, kImage,
                             "Image height in pixels (default: from the width and the camera's "
                             "aspect ratio, else 4:3)"},
                            FIELD(height), 1, 1 << 15));
    t.push_back(number<unsigned>({"spp", "spp", "penumbra:spp_requested", kPixels, kImage,
                                  "Samples per pixel", Header::Always},
                                 FIELD(spp), 1, 1u << 24));
    t.push_back(number<int>({"threads", "", "", kNotPixels, kImage, "Worker threads (0: all cores)"},
                            FIELD(threads), 0, 4096));
    t.push_back(number<unsigned long long>({"seed", "seed", "penumbra:seed", kPixels, kImage,
                                            "Random seed; the same seed gives the same image",
                                            Header::Always},
                                           FIELD(seed), 0, kInf));
    t.push_back(text({"camera", "camera", "", kPixels, kImage,
                      "Camera by name or index (default: the first camera in the file, else "
                      "one framing the whole scene)"},
                     FIELD(camera)));
    t.push_back(text({"variant", "variant", "", kPixels, kImage,
                      "glTF material variant by name (KHR_materials_variants; default: the "
                      "default materials)"},
                     FIELD(gltf.variant)));
}

}  // namespace penumbra
