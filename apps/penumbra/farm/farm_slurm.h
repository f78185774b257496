// The one place that talks to Slurm: sbatch, squeue, sacct and scontrol run as child
// processes (the real commands, found on PATH), their output parsed here.
#pragma once

#include <string>
#include <vector>

namespace penumbra {

struct CommandOutput {
    int status = -1;   // exit status; -1: could not start
    std::string text;  // stdout and stderr together
};

// Runs argv (argv[0] looked up on PATH) and captures its output.
CommandOutput run_command(const std::vector<std::string>& argv);

// sbatch --parsable ARGS SCRIPT SCRIPT_ARGS; returns the job id. Throws SceneError with
// sbatch's message when it fails.
std::string sbatch(const std::vector<std::string>& args, const std::string& script,
                   const std::vector<std::string>& script_args = {});

// MaxArraySize from `scontrol show config`; Slurm's default 1001 when it cannot be read.
size_t max_array_size();

// True while squeue still lists the job (pending, running, completing, requeued).
bool job_in_queue(const std::string& job_id);

// Progress lines for people: squeue's, and sacct's where accounting is enabled.
std::string queue_report(const std::vector<std::string>& job_ids);

// Splits --sbatch-args like a shell would for plain words and quotes ('...', "...").
std::vector<std::string> split_arguments(const std::string& text);

}  // namespace penumbra
