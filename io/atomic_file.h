// Files appear complete or not at all: every output is written to a temporary sibling
// and renamed into place, so a killed render or a full disk never leaves a truncated
// file over a good one (rename within a folder is atomic on POSIX file systems).
#pragma once

#include <functional>
#include <string>

namespace penumbra {

// Calls write(tmp) with a temporary path in path's folder (created if missing; the
// extension is kept last so OIIO picks the format from it), then renames tmp to path.
// On any exception the temporary is removed and the exception propagates; path is
// untouched. Throws SceneError if the rename fails.
void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string& tmp)>& write);

// A text file (CSV, SVG, summaries), atomically. Throws SceneError naming path.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace penumbra
