#include "job/transforms_json.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/atomic_file.h"

namespace penumbra {

using nlohmann::json;

namespace {

void put_intrinsics(json& j, const Intrinsics& k) {
    j["camera_angle_x"] = 2 * std::atan(0.5 * k.w / k.fl_x);
    j["camera_angle_y"] = 2 * std::atan(0.5 * k.h / k.fl_y);
    j["fl_x"] = k.fl_x;
    j["fl_y"] = k.fl_y;
    j["cx"] = k.cx;
    j["cy"] = k.cy;
    j["w"] = k.w;
    j["h"] = k.h;
}

// A frame's intrinsics: its own keys, else the file's.
Intrinsics get_intrinsics(const json& frame, const json& top) {
    auto number = [&](const char* key) {
        const json& from = frame.contains(key) ? frame : top;
        return from.at(key).get<double>();
    };
    Intrinsics k;
    k.w = int(number("w"));
    k.h = int(number("h"));
    k.fl_x = number("fl_x");
    k.fl_y = number("fl_y");
    k.cx = number("cx");
    k.cy = number("cy");
    return k;
}

// An exclusive lock on a folder while this lives: the farm's tasks update one
// transforms.json from several processes, and a read-merge-write must not interleave.
// Where the file system has no locks, flock fails and the update goes on unlocked.
class FolderLock {
public:
    explicit FolderLock(const std::filesystem::path& folder)
        : m_fd(::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY)) {
        if (m_fd >= 0) ::flock(m_fd, LOCK_EX);
    }
    ~FolderLock() {
        if (m_fd >= 0) ::close(m_fd);  // closing releases the lock
    }
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;

private:
    int m_fd;
};

}  // namespace

Intrinsics perspective_intrinsics(int w, int h, float yfov) {
    Intrinsics k;
    k.w = w;
    k.h = h;
    k.fl_y = 0.5 * h / std::tan(0.5 * double(yfov));
    k.fl_x = k.fl_y;
    k.cx = 0.5 * w;
    k.cy = 0.5 * h;
    return k;
}

std::string transforms_json_text(const std::vector<TransformsFrame>& frames) {
    json root = json::object();
    bool shared = !frames.empty();
    for (const TransformsFrame& f : frames)
        shared = shared && f.intrinsics == frames.front().intrinsics;
    // nerfstudio reads the distortion-free pinhole as OPENCV with zero coefficients.
    root["camera_model"] = "OPENCV";
    if (shared) put_intrinsics(root, frames.front().intrinsics);
    json list = json::array();
    for (const TransformsFrame& f : frames) {
        json frame;
        frame["file_path"] = f.file_path;
        json rows = json::array();
        for (int r = 0; r < 4; ++r)
            rows.push_back({f.transform_matrix.m[r][0], f.transform_matrix.m[r][1],
                            f.transform_matrix.m[r][2], f.transform_matrix.m[r][3]});
        frame["transform_matrix"] = rows;
        if (!shared) put_intrinsics(frame, f.intrinsics);
        list.push_back(frame);
    }
    root["frames"] = list;
    return root.dump(2) + "\n";
}

std::vector<TransformsFrame> read_transforms_json(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    std::vector<TransformsFrame> frames;
    try {
        const json root = json::parse(in);
        for (const json& f : root.at("frames")) {
            TransformsFrame frame;
            frame.file_path = f.at("file_path").get<std::string>();
            const json& rows = f.at("transform_matrix");
            for (int r = 0; r < 4; ++r)
                for (int c = 0; c < 4; ++c)
                    frame.transform_matrix.m[r][c] = rows.at(size_t(r)).at(size_t(c)).get<float>();
            frame.intrinsics = get_intrinsics(f, root);
            frames.push_back(frame);
        }
    } catch (const json::exception&) {
        return {};
    }
    return frames;
}

void update_transforms_json(const std::string& path, const std::vector<TransformsFrame>& frames) {
    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    if (!folder.empty()) std::filesystem::create_directories(folder);
    const FolderLock lock(folder);
    std::vector<TransformsFrame> all = read_transforms_json(path);
    for (const TransformsFrame& f : frames) {
        bool replaced = false;
        for (TransformsFrame& old : all)
            if (old.file_path == f.file_path) {
                old = f;
                replaced = true;
            }
        if (!replaced) all.push_back(f);
    }
    write_text_file(path, transforms_json_text(all));
}

}  // namespace penumbra
