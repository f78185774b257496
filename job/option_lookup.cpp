// Queries of the option table: an option by name, and what the header and the
// checkpoint fingerprint read from it.
#include <stdexcept>

#include "job/option_table.h"

namespace penumbra {

const OptionDecl* find_option(const std::string& flag_or_key) {
    for (const OptionDecl& d : render_option_table())
        if (d.flag == flag_or_key || (!d.job_key.empty() && d.job_key == flag_or_key)) return &d;
    return nullptr;
}

const OptionDecl& render_option(const std::string& flag) {
    const OptionDecl* d = find_option(flag);
    if (!d) throw std::logic_error("no render option --" + flag);
    return *d;
}

void set_render_option(RenderCommandOptions& o, const std::string& flag, const std::string& text) {
    render_option(flag).set(o, text);
}

Metadata option_metadata(const RenderCommandOptions& o) {
    Metadata m;
    for (const OptionDecl& d : render_option_table()) {
        if (d.header_key.empty()) continue;
        if (std::optional<MetadataValue> v = d.header(o)) m.push_back({d.header_key, *v});
    }
    return m;
}

std::string pixel_options_text(const RenderCommandOptions& o) {
    std::string s;
    for (const OptionDecl& d : render_option_table())
        if (d.pixels) s += (s.empty() ? "" : " ") + d.flag + "=" + d.get(o);
    return s;
}

}  // namespace penumbra
