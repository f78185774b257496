// Running the penumbra binary from tests: to completion with its output, or in the
// background so a test can signal it mid-render (Ctrl-C, kill -9).
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace penumbra::test {

struct CliResult {
    int status = -1;     // exit status, or 128 + signal when a signal ended it
    std::string output;  // stdout and stderr together
};

// Runs build/bin/penumbra with the arguments (no shell: no quoting needed).
CliResult run_penumbra(const std::vector<std::string>& args);

class CliProcess {
public:
    explicit CliProcess(const std::vector<std::string>& args);
    ~CliProcess();  // kills the process if still running
    CliProcess(const CliProcess&) = delete;
    CliProcess& operator=(const CliProcess&) = delete;

    // Waits until its output contains text. False on timeout or exit.
    bool wait_for_output(const std::string& text, double timeout_seconds);
    void signal(int sig);
    CliResult wait();

private:
    pid_t m_pid = -1;
    std::string m_log;
    int m_raw_status = 0;
    bool m_done = false;  // reaped
};

}  // namespace penumbra::test
