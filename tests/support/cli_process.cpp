#include "support/cli_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "support/paths.h"

namespace penumbra::test {

namespace {

int decode_status(int raw) {
    if (WIFEXITED(raw)) return WEXITSTATUS(raw);
    if (WIFSIGNALED(raw)) return 128 + WTERMSIG(raw);
    return -1;
}

}  // namespace

CliProcess::CliProcess(const std::vector<std::string>& args) {
    static int counter = 0;
    m_log = (std::filesystem::temp_directory_path() /
             ("penumbra-cli-" + std::to_string(getpid()) + "-" + std::to_string(counter++) +
              ".log"))
                .string();
    const std::string binary = binary_path("bin/penumbra");
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(binary.c_str()));
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    m_pid = fork();
    if (m_pid == 0) {
        const int fd = open(m_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(fd, 1);
        dup2(fd, 2);
        // gtest may run with SIGINT ignored or handled; the child gets the default.
        ::signal(SIGINT, SIG_DFL);
        execv(binary.c_str(), argv.data());
        _exit(127);
    }
}

CliProcess::~CliProcess() {
    if (!m_done && m_pid > 0) {
        kill(m_pid, SIGKILL);
        waitpid(m_pid, nullptr, 0);
    }
    std::remove(m_log.c_str());
}

bool CliProcess::wait_for_output(const std::string& text, double timeout_seconds) {
    const auto start = std::chrono::steady_clock::now();
    while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() <
           timeout_seconds) {
        std::ifstream log(m_log);
        if (std::string((std::istreambuf_iterator<char>(log)), {}).find(text) !=
            std::string::npos)
            return true;
        if (waitpid(m_pid, &m_raw_status, WNOHANG) != 0) {
            m_done = true;
            return false;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

void CliProcess::signal(int sig) { kill(m_pid, sig); }

CliResult CliProcess::wait() {
    if (!m_done) waitpid(m_pid, &m_raw_status, 0);
    m_done = true;
    const int raw = m_raw_status;
    std::ifstream log(m_log);
    return {decode_status(raw), std::string((std::istreambuf_iterator<char>(log)), {})};
}

CliResult run_penumbra(const std::vector<std::string>& args) { return CliProcess(args).wait(); }

}  // namespace penumbra::test
