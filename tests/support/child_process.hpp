#pragma once
// A child process for tests that run programs: started in its own process group with its
// stdout and stderr piped, read line by line with a deadline, and on destruction (or stop())
// ended with SIGTERM, then SIGKILL after a grace period, the whole group at once (xvfb-run and
// the X server it starts included).

#include <chrono>
#include <optional>
#include <string>
#include <sys/types.h>
#include <vector>

namespace carrom::test_support {

class ChildProcess {
public:
    enum class Stream { Out, Err };

    // `env`: "NAME=value" entries set (or replaced) in the child's copy of this environment.
    // `stderr_path`: when not empty, the child's stderr is appended to this file (created if
    // missing) instead of a pipe, and lines(Stream::Err) stays empty; a chatty child cannot
    // block on a pipe nobody reads.
    explicit ChildProcess(const std::vector<std::string>& argv,
                          const std::vector<std::string>& env = {},
                          const std::string& stderr_path = {});
    ~ChildProcess();
    ChildProcess(const ChildProcess&) = delete;
    ChildProcess& operator=(const ChildProcess&) = delete;

    bool started() const { return pid_ > 0; }
    pid_t pid() const { return pid_; } // for signals of the test's own (SIGHUP)
    // The next line on `stream` that starts with `prefix` (lines before it are kept in
    // lines(stream)); nothing if the deadline passes or the stream ends first.
    std::optional<std::string> wait_line(Stream stream, const std::string& prefix,
                                         std::chrono::steady_clock::time_point deadline);
    // Waits for the process to exit; its exit code (128 + signal if killed), or nothing if
    // the deadline passes.
    std::optional<int> wait_exit(std::chrono::steady_clock::time_point deadline);
    // Ends the process group (SIGTERM, then SIGKILL after `grace`) and reaps the process.
    void stop(std::chrono::milliseconds grace = std::chrono::milliseconds(2000));
    // Kills the process group at once (SIGKILL: no shutdown of its own) and reaps the process.
    void kill_now();
    // Everything read so far from `stream`, line by line.
    const std::vector<std::string>& lines(Stream stream) const;
    // Everything read so far, stdout's lines then stderr's, each ending in a newline (for test
    // failure messages).
    std::string output() const;

private:
    struct Pipe {
        int fd = -1;
        std::string partial;
        std::vector<std::string> lines;
        std::size_t handed_out = 0;
    };
    // Reads what is available on both pipes, waiting at most `wait`.
    void pump(std::chrono::milliseconds wait);
    Pipe& pipe(Stream s) { return s == Stream::Out ? out_ : err_; }
    bool reap(bool block);
    static std::vector<std::string> environment(const std::vector<std::string>& changes);

    pid_t pid_ = -1;
    std::optional<int> exit_code_;
    Pipe out_;
    Pipe err_;
};

} // namespace carrom::test_support
