#include "apps/penumbra/study/converge_command.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "apps/penumbra/study/converge_measure.h"
#include "apps/penumbra/option_cli.h"
#include "apps/penumbra/scene_setup.h"
#include "study/svg_plot.h"
#include "core/film/image_error.h"
#include "study/convergence.h"
#include "core/error.h"
#include "core/log.h"
#include "core/progress.h"
#include "io/atomic_file.h"
#include "io/image/image_writer.h"
#include "io/image/render_writer.h"
#include "job/option_table.h"

namespace penumbra {

namespace fs = std::filesystem;

void add_converge_command(CLI::App& app, ConvergeOptions& o) {
    CLI::App* cmd = app.add_subcommand(
        "converge",
        "Measure error against time: render at doubling spp (or time checkpoints) in one or "
        "more configurations, compare with a reference, write CSV, SVG plot and summary");
    cmd->add_option("scene", o.scene, "Scene file (.gltf or .glb)")
        ->required()
        ->check(CLI::ExistingFile);
    auto* ref = cmd->add_option("--reference", o.reference, "Reference EXR (sets the size)")
                    ->check(CLI::ExistingFile);
    cmd->add_option("--reference-spp", o.reference_spp,
                    "Render the reference first with this many spp (another seed), saved as "
                    "OUT_DIR/reference.exr")
        ->check(CLI::Range(1u, 1u << 24))
        ->excludes(ref);
    cmd->add_option("-o,--out-dir", o.out_dir,
                    "Folder for convergence.csv, convergence.svg, summary.txt")
        ->required();
    cmd->add_option("--max-spp", o.max_spp,
                    "Largest sample count (also the sampler's layout with --times)")
        ->capture_default_str()
        ->check(CLI::Range(1u, 1u << 24));
    cmd->add_option("--min-spp", o.min_spp, "First sample count; doubled up to --max-spp")
        ->capture_default_str()
        ->check(CLI::Range(1u, 1u << 24));
    cmd->add_option("--times", o.times,
                    "Time checkpoints in seconds instead of doubling spp: one render with "
                    "that --time-limit each")
        ->delimiter(',')
        ->check(CLI::PositiveNumber);
    cmd->add_option("--compare", o.compare,
                    "Configurations 'name=OPTIONS;name=OPTIONS', OPTIONS being image options, "
                    "e.g. 'mis=--strategy mis;bsdf=--strategy bsdf'");
    cmd->add_option("--config", o.configs, "A configuration NAME:OPTIONS (repeatable)");
    cmd->add_option("--target-relmse", o.target_relmse,
                    "Report the time each configuration takes to reach this relMSE")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    cmd->add_option("--relmse-epsilon", o.epsilon,
                    "relMSE = mean((x - r)^2 / (r^2 + epsilon)); epsilon keeps black pixels "
                    "from dominating")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
    cmd->add_option("--clock", o.clock,
                    "Time for the plot, MSE*time and the time to the target: wall (elapsed) "
                    "or cpu (CPU time of all threads, steadier on a busy machine)")
        ->capture_default_str()
        ->check(CLI::IsMember({"wall", "cpu"}));
    cmd->add_flag("--bias-variance", o.bias_variance,
                  "Split relMSE into the variance estimated from two independent halves of "
                  "the samples and the rest (bias^2 and the reference's noise): shows what "
                  "clamping or regularization trade");
    add_declared_options(cmd, o.base, is_image_option);
}

namespace {

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// A configuration is the base options with its own image options parsed over them.
ConvergeConfig parse_config(const RenderCommandOptions& base, const std::string& name,
                            const std::string& args) {
    ConvergeConfig c{trim(name), base};
    if (c.name.empty()) throw SceneError("configuration '" + args + "' has no name");
    CLI::App parser{"configuration " + c.name};
    add_declared_options(&parser, c.options, is_image_option);
    try {
        parser.parse(args, false);
    } catch (const CLI::ParseError& e) {
        throw SceneError("configuration '" + c.name + "' (" + args + "): " + e.what());
    }
    return c;
}

std::vector<ConvergeConfig> configs_of(const ConvergeOptions& o) {
    std::vector<ConvergeConfig> configs;
    std::stringstream items(o.compare);
    std::string item;
    while (std::getline(items, item, ';')) {
        if (trim(item).empty()) continue;
        const size_t eq = item.find('=');
        if (eq == std::string::npos)
            throw SceneError("--compare '" + item + "': expected name=OPTIONS");
        configs.push_back(parse_config(o.base, item.substr(0, eq), item.substr(eq + 1)));
    }
    for (const std::string& c : o.configs) {
        const size_t colon = c.find(':');
        if (colon == std::string::npos)
            throw SceneError("--config '" + c + "': expected NAME:OPTIONS");
        configs.push_back(parse_config(o.base, c.substr(0, colon), c.substr(colon + 1)));
    }
    if (configs.empty()) configs.push_back({"default", o.base});
    return configs;
}

Image render_image(const SceneSetup& s, const RenderOptions& ropt, RenderStats& stats) {
    return render(s.context(), *s.camera, *s.integrator, ropt, &stats).resolve();
}

Image render_reference(const ConvergeOptions& o, const RenderCommandOptions& base) {
    RenderCommandOptions ro = base;
    ro.spp = o.reference_spp;
    // Other sample streams than the measured renders: sharing their first samples would
    // correlate reference and image and understate the error.
    ro.seed = base.seed ^ 0x9e3779b97f4a7c15ull;
    // The reference is the raw estimate: no sample split or guides for a denoiser.
    ro.denoise = false;
    const std::unique_ptr<SceneSetup> s = setup_scene(ro, o.scene);
    RenderStats stats;
    const Image ref = render_image(*s, render_options_for(ro, "reference"), stats);
    const std::string path = (fs::path(o.out_dir) / "reference.exr").string();
    write_exr(path, ref,
              {{"penumbra:scene", o.scene},
               {"penumbra:spp", std::to_string(stats.spp)},
               {"penumbra:seed", std::to_string(ro.seed)},
               {"penumbra:sampler", sampler_name(sampler_in_effect(ro.sampler, ro.spp))},
               {"penumbra:integrator", render_option("integrator").get(ro)}});
    if (!base.quiet)
        std::printf("reference: %u spp in %s -> %s\n", stats.spp,
                    format_duration(stats.seconds).c_str(), path.c_str());
    return ref;
}

std::string fmt(const char* format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

// One line of the summary table.
std::string row(const std::string& config, const std::string& spp, const std::string& time,
                const std::string& mse, const std::string& relmse, const std::string& mse_time,
                const std::string& slope, const std::string& reach) {
    char line[512];
    std::snprintf(line, sizeof line, "%-14s %7s %9s %11s %11s %11s %7s  %s\n", config.c_str(),
                  spp.c_str(), time.c_str(), mse.c_str(), relmse.c_str(), mse_time.c_str(),
                  slope.c_str(), reach.c_str());
    return line;
}

}  // namespace

namespace {

std::string csv_header(const ConvergeOptions& o, bool denoise) {
    // mse_x_time and relmse_x_time: inverse efficiency, with the --clock time.
    // mean_spp: below spp where adaptive sampling stopped pixels early; target_error: the
    // adaptive target (0: none); variance and bias2 with --bias-variance (empty for a
    // denoised row); denoised (0 or 1) and the denoiser's relmse_estimate where some
    // configuration denoises.
    return std::string(
               "config,spp,seconds,cpu_seconds,mse,relmse,mse_x_time,relmse_x_time,mean_spp,"
               "target_error") +
           (o.bias_variance ? ",variance,bias2" : "") +
           (denoise ? ",denoised,relmse_estimate" : "") + "\n";
}

std::string csv_line(const ConvergeOptions& o, bool denoise, const ConvergeSeries& s,
                     const ConvergePoint& p) {
    const double t = p.time(o.clock);
    std::string line = s.config + "," + std::to_string(p.spp) + fmt(",%.6g", p.seconds) +
                       fmt(",%.6g", p.cpu_seconds) + fmt(",%.6g", p.mse) + fmt(",%.6g", p.relmse) +
                       fmt(",%.6g", p.mse * t) + fmt(",%.6g", p.relmse * t) +
                       fmt(",%.6g", p.mean_spp) + fmt(",%.6g", p.target_error);
    if (o.bias_variance)
        line += s.denoised ? ",," : fmt(",%.6g", p.variance) + fmt(",%.6g", p.relmse - p.variance);
    if (denoise) line += s.denoised ? ",1" + fmt(",%.6g", p.relmse_estimate) : std::string(",0,");
    return line + "\n";
}

// The summary table's row: the series' last checkpoint, its slope and time to the target.
std::string table_row(const ConvergeOptions& o, const ConvergeSeries& s, PlotSeries& plot) {
    std::vector<double> spp, mse;
    for (const ConvergePoint& p : s.points) {
        plot.x.push_back(p.time(o.clock));
        plot.y.push_back(p.relmse);
        spp.push_back(p.mean_spp);
        mse.push_back(p.mse);
    }
    const std::optional<double> slope = log_log_slope(spp, mse);
    const std::optional<TimeToError> reach = time_to_error(plot.x, plot.y, o.target_relmse);
    const ConvergePoint& last = s.points.back();
    const double t = last.time(o.clock);
    return row(s.name, std::to_string(last.spp), fmt("%.3f", t), fmt("%.4e", last.mse),
               fmt("%.4e", last.relmse), fmt("%.4e", last.mse * t),
               slope ? fmt("%.3f", *slope) : "-",
               reach ? (reach->at_most ? "<= " : "") + fmt("%.3g s", reach->seconds) +
                           (reach->extrapolated ? " (extrapolated)" : "")
                     : "not reached");
}

// --bias-variance: the last checkpoint's relMSE split, one line per raw series.
std::string bias_variance_lines(const std::vector<ConvergeSeries>& all) {
    std::string out =
        "\nrelMSE = variance (from the two halves) + bias^2 (and the reference's noise), last "
        "checkpoint:\n";
    for (const ConvergeSeries& s : all) {
        if (s.denoised) continue;
        const ConvergePoint& p = s.points.back();
        char line[256];
        std::snprintf(line, sizeof line, "%-14s relMSE %.4e = variance %.4e + bias^2 %.4e\n",
                      s.name.c_str(), p.relmse, p.variance, p.relmse - p.variance);
        out += line;
    }
    return out;
}

// Each denoised series beside its raw one at the last checkpoint, with the denoiser's
// own estimate against the measured relMSE.
std::string denoise_lines(const ConvergeOptions& o, const std::vector<ConvergeSeries>& all) {
    std::string out =
        "\nraw and denoised, last checkpoint (the denoiser estimates its relMSE with "
        "epsilon " +
        fmt("%g", kRelMseEpsilon) + "):\n";
    for (size_t i = 1; i < all.size(); ++i) {
        if (!all[i].denoised) continue;
        const ConvergePoint &raw = all[i - 1].points.back(), &dn = all[i].points.back();
        char line[320];
        std::snprintf(line, sizeof line,
                      "%-14s relMSE raw %.4e, denoised %.4e (%.3gx lower; %s more), estimate "
                      "%.4e (%.3gx the measured)\n",
                      all[i].config.c_str(), raw.relmse, dn.relmse,
                      dn.relmse > 0 ? raw.relmse / dn.relmse : 0.0,
                      format_duration(dn.time(o.clock) - raw.time(o.clock)).c_str(),
                      dn.relmse_estimate, dn.relmse > 0 ? dn.relmse_estimate / dn.relmse : 0.0);
        out += line;
    }
    return out;
}

}  // namespace

int run_converge_command(const ConvergeOptions& o) {
    if (o.base.quiet) set_log_level(LogLevel::Error);
    if (o.reference.empty() && o.reference_spp == 0)
        throw SceneError("converge needs --reference REF.exr or --reference-spp N");
    if (o.min_spp > o.max_spp) throw SceneError("--min-spp is larger than --max-spp");
    fs::create_directories(o.out_dir);
    ConvergeOptions opts = o;
    Image ref;
    if (!o.reference.empty()) {
        ref = read_beauty(o.reference);
        // The reference decides the size unless the user did.
        if (o.base.width == 0 && o.base.height == 0) {
            opts.base.width = ref.width;
            opts.base.height = ref.height;
        }
    }
    const std::vector<ConvergeConfig> configs = configs_of(opts);
    if (o.reference.empty()) ref = render_reference(opts, opts.base);

    std::vector<ConvergeSeries> all;
    for (const ConvergeConfig& c : configs)
        for (ConvergeSeries& s : measure_config(opts, c, ref)) all.push_back(std::move(s));
    const bool denoise =
        std::any_of(all.begin(), all.end(), [](const ConvergeSeries& s) { return s.denoised; });
    std::string csv = csv_header(o, denoise);
    std::string table = row("config", "spp", o.clock + " s", "MSE", "relMSE", "MSE*s", "slope",
                            "time to relMSE " + fmt("%g", o.target_relmse));
    std::vector<PlotSeries> series;
    for (const ConvergeSeries& s : all) {
        for (const ConvergePoint& p : s.points) csv += csv_line(o, denoise, s, p);
        PlotSeries plot{s.name, {}, {}};
        table += table_row(o, s, plot);
        series.push_back(std::move(plot));
    }
    if (o.bias_variance) table += bias_variance_lines(all);
    if (denoise) table += denoise_lines(o, all);
    const std::string summary =
        "penumbra converge " + o.scene + ": " + std::to_string(ref.width) + "x" +
        std::to_string(ref.height) + ", reference " +
        (o.reference.empty() ? std::to_string(o.reference_spp) + " spp (rendered)" : o.reference) +
        ", relMSE epsilon " + fmt("%g", o.epsilon) + ", " + o.clock + " clock\n" +
        "last checkpoint per configuration; slope: least-squares fit of log(MSE) against "
        "log(spp)\n" +
        table;
    const fs::path dir(o.out_dir);
    write_text_file((dir / "convergence.csv").string(), csv);
    write_text_file(
        (dir / "convergence.svg").string(),
        log_log_plot_svg(series, {"Convergence: " + fs::path(o.scene).filename().string(),
                                  "render time (s, " + o.clock + " clock)", "relMSE"}));
    write_text_file((dir / "summary.txt").string(), summary);
    std::printf("%s", summary.c_str());
    std::printf("wrote %s, %s, %s\n", (dir / "convergence.csv").c_str(),
                (dir / "convergence.svg").c_str(), (dir / "summary.txt").c_str());
    return 0;
}

}  // namespace penumbra
