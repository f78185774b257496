// `penumbra farm`: a job file rendered as a Slurm array job (submit), its progress
// (status), and the two steps Slurm runs: one work item per array task (task) and the
// assembly of bands and the batch summary once all tasks ended (merge).
#pragma once

#include <string>

namespace CLI {
class App;  // CLI/CLI.hpp, which only the .cpp files that build commands include
}

namespace penumbra {

struct FarmOptions {
    std::string job_file;
    // submit
    std::string partition;
    int cpus_per_task = 0;  // 0: Slurm's default (one CPU)
    int max_running = 0;    // 0: no limit (the array's %K)
    std::string sbatch_args;
    bool wait = false;
    double checkpoint_interval = 300;  // seconds, for every task (render --checkpoint-interval)
    // task
    size_t offset = 0, index = 0;  // work item offset + index (an array chunk's first item)
};

// Adds `farm` with its subcommands; returns it for run_farm_command.
CLI::App* add_farm_command(CLI::App& app, FarmOptions& options);
// Runs the subcommand given; returns the exit status.
int run_farm_command(const CLI::App& farm, const FarmOptions& options);

}  // namespace penumbra
