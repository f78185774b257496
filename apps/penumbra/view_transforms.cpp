#include "apps/penumbra/view_transforms.h"

#include <filesystem>
#include <map>

#include "core/log.h"
#include "io/image/image_writer.h"
#include "job/transforms_json.h"

namespace penumbra {

namespace fs = std::filesystem;

void write_view_transforms(const std::vector<BatchJob>& jobs, const std::vector<JobResult>& results,
                           size_t first_result, size_t group, const SceneSetup& setup) {
    std::map<fs::path, std::vector<TransformsFrame>> by_folder;
    for (size_t i = 0; i < jobs.size() && first_result + i < results.size(); ++i) {
        const BatchJob& job = jobs[i];
        const JobResult& r = results.at(first_result + i);
        if (job.group != group || job.view < 0 || job.band >= 0 || r.output.empty() ||
            r.status == JobStatus::Failed)
            continue;
        const fs::path image =
            job.options.no_preview ? fs::path(r.output) : fs::path(preview_path_for(r.output));
        if (!fs::exists(image)) continue;
        const CameraDesc& cam = setup.views.at(size_t(job.view));
        TransformsFrame frame;
        frame.file_path = image.filename().string();
        frame.transform_matrix = cam.to_world.matrix();
        frame.intrinsics = perspective_intrinsics(setup.width, setup.height, cam.yfov);
        by_folder[image.parent_path()].push_back(frame);
    }
    for (const auto& [folder, frames] : by_folder) {
        const std::string path = (folder / "transforms.json").string();
        try {
            update_transforms_json(path, frames);
        } catch (const std::exception& e) {
            LOG_WARNING(path << ": not written: " << e.what());
        }
    }
}

}  // namespace penumbra
