#include "apps/penumbra/farm/farm_slurm.h"

#include <sys/wait.h>
#include <unistd.h>

#include <sstream>

#include "core/error.h"

namespace penumbra {

CommandOutput run_command(const std::vector<std::string>& argv) {
    CommandOutput out;
    int fds[2];
    if (argv.empty() || pipe(fds) != 0) return out;
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return out;
    }
    if (pid == 0) {
        dup2(fds[1], STDOUT_FILENO);
        dup2(fds[1], STDERR_FILENO);
        close(fds[0]);
        close(fds[1]);
        std::vector<char*> args;
        for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execvp(args[0], args.data());
        _exit(127);
    }
    close(fds[1]);
    char buf[4096];
    ssize_t n;
    while ((n = read(fds[0], buf, sizeof buf)) > 0) out.text.append(buf, size_t(n));
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    out.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    if (out.status == 127 && out.text.empty()) out.text = argv[0] + ": not found on PATH";
    return out;
}

std::string sbatch(const std::vector<std::string>& args, const std::string& script,
                   const std::vector<std::string>& script_args) {
    std::vector<std::string> argv = {"sbatch", "--parsable"};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.push_back(script);
    argv.insert(argv.end(), script_args.begin(), script_args.end());
    const CommandOutput r = run_command(argv);
    // --parsable prints "jobid" or "jobid;cluster".
    std::string id = r.text.substr(0, r.text.find_first_of(";\n"));
    if (r.status != 0 || id.empty() || id.find_first_not_of("0123456789") != std::string::npos)
        throw SceneError("sbatch " + script + " failed (status " + std::to_string(r.status) +
                         "): " + r.text);
    return id;
}

size_t max_array_size() {
    const CommandOutput r = run_command({"scontrol", "show", "config"});
    std::istringstream lines(r.text);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("MaxArraySize", 0) != 0) continue;
        const size_t eq = line.find('=');
        if (eq == std::string::npos) break;
        try {
            return std::stoul(line.substr(eq + 1));
        } catch (const std::exception&) {
            break;
        }
    }
    return 1001;
}

bool job_in_queue(const std::string& job_id) {
    const CommandOutput r = run_command({"squeue", "-h", "-j", job_id, "-o", "%i"});
    // squeue fails for a job id it has forgotten: the job is long done.
    return r.status == 0 && r.text.find_first_not_of(" \n") != std::string::npos;
}

std::string queue_report(const std::vector<std::string>& job_ids) {
    std::string ids;
    for (const std::string& id : job_ids) ids += (ids.empty() ? "" : ",") + id;
    std::string out = run_command({"squeue", "-j", ids, "-o", "%.18i %.9T %.10M %.20R"}).text;
    const CommandOutput acct =
        run_command({"sacct", "-X", "-j", ids, "--format=JobID%20,State,Elapsed,ExitCode,MaxRSS"});
    if (acct.status == 0) out += acct.text;
    return out;
}

std::vector<std::string> split_arguments(const std::string& text) {
    std::vector<std::string> words;
    std::string word;
    bool in_word = false;
    char quote = 0;
    for (char c : text) {
        if (quote) {
            if (c == quote)
                quote = 0;
            else
                word += c;
        } else if (c == '\'' || c == '"') {
            quote = c;
            in_word = true;
        } else if (c == ' ' || c == '\t' || c == '\n') {
            if (in_word) words.push_back(word);
            word.clear();
            in_word = false;
        } else {
            word += c;
            in_word = true;
        }
    }
    if (quote) throw SceneError("--sbatch-args: unterminated quote in '" + text + "'");
    if (in_word) words.push_back(word);
    return words;
}

}  // namespace penumbra
