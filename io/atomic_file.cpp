#include "io/atomic_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace penumbra {

namespace fs = std::filesystem;

void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string& tmp)>& write) {
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    fs::create_directories(dir, ec);
    // The process id keeps two renders writing the same name from sharing a temporary.
    const fs::path tmp =
        dir / (".tmp-" + std::to_string(getpid()) + "-" + target.filename().string());
    try {
        write(tmp.string());
    } catch (...) {
        fs::remove(tmp, ec);
        throw;
    }
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw SceneError(path + ": cannot move the finished file into place: " + ec.message());
    }
}

void write_text_file(const std::string& path, const std::string& text) {
    write_file_atomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        if (!out) throw SceneError(path + ": cannot write");
    });
}

}  // namespace penumbra
