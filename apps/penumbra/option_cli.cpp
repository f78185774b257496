#include "apps/penumbra/option_cli.h"

#include <CLI/CLI.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace penumbra {

namespace {

std::string names_of(const OptionDecl& d) {
    return (d.short_flag.empty() ? "" : "-" + d.short_flag + ",") + "--" + d.flag;
}

// Sets the option, turning the table's std::invalid_argument into CLI11's error (which
// names the option).
void set_or_fail(const OptionDecl& d, RenderCommandOptions& o, const std::string& text) {
    try {
        d.set(o, text);
    } catch (const std::invalid_argument& e) {
        throw CLI::ValidationError("--" + d.flag, e.what());
    }
}

void add_one(CLI::App* cmd, RenderCommandOptions& o, const OptionDecl& d) {
    const std::string names = names_of(d);
    if (d.kind == OptionKind::Flag) {
        cmd->add_flag_callback(names, [&o, &d] { set_or_fail(d, o, "1"); }, d.help);
        return;
    }
    CLI::Option* opt = nullptr;
    if (d.kind == OptionKind::Numbers) {
        opt = cmd->add_option_function<std::vector<std::string>>(
                     names,
                     [&o, &d](const std::vector<std::string>& words) {
                         std::string text;
                         for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
                         set_or_fail(d, o, text);
                     },
                     d.help)
                  ->expected(d.count);
    } else {
        opt = cmd->add_option_function<std::string>(
            names, [&o, &d](const std::string& text) { set_or_fail(d, o, text); }, d.help);
    }
    switch (d.kind) {
        case OptionKind::Integer: opt->type_name("INT"); break;
        case OptionKind::Number:
        case OptionKind::Numbers: opt->type_name("FLOAT"); break;
        case OptionKind::Path: opt->type_name("PATH"); break;
        default: opt->type_name("TEXT"); break;
    }
    const std::string current = d.get(o);
    if (!current.empty() && d.kind != OptionKind::Path) opt->default_str(current);
    if (d.existing_file) {
        if (d.choices.empty()) opt->check(CLI::ExistingFile);
        else opt->check(CLI::ExistingFile | CLI::IsMember(d.choices));
    } else if (d.kind == OptionKind::Choice) {
        opt->check(CLI::IsMember(d.choices));
    }
}

}  // namespace

void add_declared_options(CLI::App* cmd, RenderCommandOptions& o,
                          const std::function<bool(const OptionDecl&)>& wanted) {
    for (const OptionDecl& d : render_option_table())
        if (wanted(d)) add_one(cmd, o, d);
}

bool is_image_option(const OptionDecl& d) { return d.scope == OptionScope::Image; }
bool is_render_option(const OptionDecl& d) { return d.scope != OptionScope::Farm; }

bool is_timeline_option(const OptionDecl& d) {
    return d.scope == OptionScope::Image && (d.timing || d.flag == "fps" || d.flag == "shutter");
}

}  // namespace penumbra
