// penumbra: the command-line front end. Parses options, runs a subcommand, and turns
// every error into one line on stderr and a non-zero exit status.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

#include "apps/penumbra/study/check_accel_command.h"
#include "apps/penumbra/study/converge_command.h"
#include "apps/penumbra/farm/farm_command.h"
#include "apps/penumbra/render_command.h"
#include "core/log.h"

int main(int argc, char** argv) {
    CLI::App app{
        "penumbra: a physically based path tracer for glTF 2.0 scenes.\n"
        "Renders .gltf/.glb files to linear OpenEXR images with PNG previews."};
    app.require_subcommand(1);
    app.footer(
        "Examples:\n"
        "  penumbra render scenes/cornell-box.gltf -o out/cornell-box.exr --spp 64\n"
        "  penumbra render a.gltf b.glb --out-dir renders --width 1024 --integrator path\n"
        "  penumbra render scenes/*.gltf --out-dir renders --name '{scene}_{camera}.exr'\n"
        "  penumbra render --job jobs.json --time-limit 60\n"
        "  penumbra converge scenes/cornell-box.gltf --reference-spp 4096 -o conv \\\n"
        "      --compare 'independent=--sampler independent;sobol=--sampler sobol'\n"
        "  penumbra check-accel scenes/cornell-box.gltf\n"
        "  penumbra farm submit jobs.json --cpus-per-task 8 --wait\n"
        "Run 'penumbra SUBCOMMAND --help' for the options of each subcommand.");
    app.set_version_flag("--version", std::string("penumbra ") + PENUMBRA_VERSION);

    penumbra::RenderCommandOptions render_options;
    penumbra::add_render_command(app, render_options);
    penumbra::CheckAccelOptions check_accel_options;
    penumbra::add_check_accel_command(app, check_accel_options);
    penumbra::ConvergeOptions converge_options;
    penumbra::add_converge_command(app, converge_options);
    penumbra::FarmOptions farm_options;
    CLI::App* farm = penumbra::add_farm_command(app, farm_options);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    try {
        if (app.got_subcommand("render")) return penumbra::run_render_command(render_options);
        if (app.got_subcommand("check-accel"))
            return penumbra::run_check_accel_command(check_accel_options);
        if (app.got_subcommand("converge"))
            return penumbra::run_converge_command(converge_options);
        if (app.got_subcommand("farm")) return penumbra::run_farm_command(*farm, farm_options);
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
