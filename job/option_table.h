// The render options, each declared once: its name, type, default, allowed values, help,
// job-file key, header key, and whether it decides pixels. The command line
// (apps/penumbra/option_cli.cpp), job files (job_file.cpp), the EXR header
// (render_metadata.cpp), the checkpoint fingerprint (render_checkpoint.cpp) and the farm
// plan all read this table; adding an option means one entry in option_table.cpp and the
// field its consumer reads.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/image/image_writer.h"
#include "job/render_options.h"

namespace penumbra {

enum class OptionKind {
    Flag,     // present or not (job file: true / false)
    Integer,  // whole number in a range
    Number,   // real number in a range
    Text,     // free text (a name, a list)
    Path,     // a file or folder; job files resolve it against their own folder
    Choice,   // one of `choices`
    Numbers,  // `count` real numbers (command line: separate words; job file: an array)
};

// Which commands take it: every image option is also a `converge --config` option; farm
// options are job-file keys only (`render` renders whole images).
enum class OptionScope { Image, Render, Farm };

struct OptionDecl {
    std::string flag;        // "time-limit" is --time-limit
    std::string short_flag;  // "o" is -o; empty: none
    std::string job_key;     // "time_limit"; empty: not a job-file key
    std::string header_key;  // empty: not echoed in the EXR header
    bool pixels = false;     // decides pixels: part of the checkpoint fingerprint
    OptionScope scope = OptionScope::Image;
    OptionKind kind = OptionKind::Text;
    std::string help;
    std::vector<std::string> choices;  // Choice: the names, in the order of the help
    int count = 1;                     // Numbers: how many
    bool existing_file = false;        // Path: must name an existing file (or a choice)
    // Path: values starting with this are not file names ("orbit:" of --views), so a job
    // file leaves them as they are instead of resolving them against its folder.
    std::string keyword_prefix;
    // A frame, frame list, time or shutter interval: a job entry giving one replaces all
    // the timing it inherits.
    bool timing = false;

    // A job file's key, where it means more than `set`: "frame" there is a frame list of
    // one, named as frames are. Null: `set`.
    std::function<void(RenderCommandOptions&, const std::string&)> job_set;

    // The value as text that `set` reads back exactly ("" when unset).
    std::function<std::string(const RenderCommandOptions&)> get;
    // Sets it from text; throws std::invalid_argument saying what is wrong.
    std::function<void(RenderCommandOptions&, const std::string&)> set;
    // The header's value (nullopt: not written for these options).
    std::function<std::optional<MetadataValue>(const RenderCommandOptions&)> header;
};

const std::vector<OptionDecl>& render_option_table();
// By flag ("time-limit") or job key ("time_limit"); nullptr when there is none.
const OptionDecl* find_option(const std::string& flag_or_key);
// The declared option; throws std::logic_error when there is none (a programming error).
const OptionDecl& render_option(const std::string& flag);

// Sets `flag` from text as the command line would: for tests and tools.
void set_render_option(RenderCommandOptions& o, const std::string& flag, const std::string& text);

// The header entries of every option that has a header key, in table order.
Metadata option_metadata(const RenderCommandOptions& o);
// "key=value" for every option that decides pixels, in table order, space-separated.
std::string pixel_options_text(const RenderCommandOptions& o);

// The sampler's name as --sampler spells it: what an image's header records in effect.
std::string sampler_name(SamplerType type);

}  // namespace penumbra
