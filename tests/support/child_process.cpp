#include "support/child_process.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace carrom::test_support {
namespace {

void close_fd(int& fd) {
    if (fd >= 0) {
        ::close(fd);
        fd = -1;
    }
}

} // namespace

std::vector<std::string> ChildProcess::environment(const std::vector<std::string>& changes) {
    std::vector<std::string> out;
    for (char** e = environ; *e != nullptr; ++e) {
        out.emplace_back(*e);
    }
    for (const std::string& change : changes) {
        const std::string name = change.substr(0, change.find('=') + 1);
        std::erase_if(out, [&name](const std::string& e) { return e.rfind(name, 0) == 0; });
        out.push_back(change);
    }
    return out;
}

ChildProcess::ChildProcess(const std::vector<std::string>& argv,
                           const std::vector<std::string>& env, const std::string& stderr_path) {
    int out[2] = {-1, -1};
    int err[2] = {-1, -1};
    const bool err_to_file = !stderr_path.empty();
    if (argv.empty() || ::pipe(out) != 0 || (!err_to_file && ::pipe(err) != 0)) {
        close_fd(out[0]);
        close_fd(out[1]);
        return;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, out[0]);
    if (err_to_file) {
        posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderr_path.c_str(),
                                         O_WRONLY | O_CREAT | O_APPEND, 0644);
    } else {
        posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
        posix_spawn_file_actions_addclose(&actions, err[0]);
    }
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attr, 0); // its own group, so stop() reaches its children too
    std::vector<char*> args;
    for (const std::string& a : argv) {
        args.push_back(const_cast<char*>(a.c_str()));
    }
    args.push_back(nullptr);
    std::vector<std::string> env_strings = environment(env);
    std::vector<char*> envp;
    for (std::string& e : env_strings) {
        envp.push_back(e.data());
    }
    envp.push_back(nullptr);
    pid_t pid = -1;
    if (::posix_spawnp(&pid, args[0], &actions, &attr, args.data(), envp.data()) == 0) {
        pid_ = pid;
    }
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    close_fd(out[1]);
    close_fd(err[1]);
    out_.fd = out[0];
    err_.fd = err[0];
    for (int fd : {out_.fd, err_.fd}) {
        if (fd >= 0) {
            ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) | O_NONBLOCK);
        }
    }
}

ChildProcess::~ChildProcess() {
    stop();
    close_fd(out_.fd);
    close_fd(err_.fd);
}

void ChildProcess::pump(std::chrono::milliseconds wait) {
    pollfd fds[2];
    nfds_t n = 0;
    for (Pipe* p : {&out_, &err_}) {
        if (p->fd >= 0) {
            fds[n++] = {p->fd, POLLIN, 0};
        }
    }
    if (n == 0) {
        std::this_thread::sleep_for(wait);
        return;
    }
    if (::poll(fds, n, static_cast<int>(wait.count())) <= 0) {
        return;
    }
    for (Pipe* p : {&out_, &err_}) {
        char buf[4096];
        bool ended = false;
        while (p->fd >= 0) {
            const ssize_t got = ::read(p->fd, buf, sizeof buf);
            if (got > 0) {
                p->partial.append(buf, static_cast<std::size_t>(got));
                continue;
            }
            if (got == 0) {
                ended = true;
                close_fd(p->fd);
            }
            break; // EAGAIN or end
        }
        std::size_t nl = 0;
        while ((nl = p->partial.find('\n')) != std::string::npos) {
            p->lines.push_back(p->partial.substr(0, nl));
            p->partial.erase(0, nl + 1);
        }
        if (ended && !p->partial.empty()) { // end of stream: keep a last unterminated line
            p->lines.push_back(p->partial);
            p->partial.clear();
        }
    }
}

std::optional<std::string> ChildProcess::wait_line(Stream stream, const std::string& prefix,
                                                   std::chrono::steady_clock::time_point deadline) {
    Pipe& p = pipe(stream);
    for (;;) {
        while (p.handed_out < p.lines.size()) {
            const std::string& line = p.lines[p.handed_out++];
            if (line.rfind(prefix, 0) == 0) {
                return line;
            }
        }
        const auto now = std::chrono::steady_clock::now();
        if (now >= deadline || p.fd < 0) {
            return std::nullopt;
        }
        pump(std::min(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now),
                      std::chrono::milliseconds(100)));
    }
}

bool ChildProcess::reap(bool block) {
    if (pid_ <= 0 || exit_code_) {
        return true;
    }
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, block ? 0 : WNOHANG);
    if (r != pid_) {
        return false;
    }
    exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return true;
}

std::optional<int> ChildProcess::wait_exit(std::chrono::steady_clock::time_point deadline) {
    while (!reap(false)) {
        if (std::chrono::steady_clock::now() >= deadline) {
            return std::nullopt;
        }
        pump(std::chrono::milliseconds(50));
    }
    pump(std::chrono::milliseconds(0));
    return exit_code_;
}

void ChildProcess::stop(std::chrono::milliseconds grace) {
    if (pid_ <= 0) {
        return;
    }
    // The group may outlive its leader (xvfb-run's X server), so it is signalled either way.
    ::kill(-pid_, SIGTERM);
    const auto deadline = std::chrono::steady_clock::now() + grace;
    while (!reap(false) && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(-pid_, SIGKILL);
    reap(true);
    pid_ = -1;
}

void ChildProcess::kill_now() {
    if (pid_ <= 0) {
        return;
    }
    ::kill(-pid_, SIGKILL);
    reap(true);
    pid_ = -1;
}

const std::vector<std::string>& ChildProcess::lines(Stream stream) const {
    return stream == Stream::Out ? out_.lines : err_.lines;
}

std::string ChildProcess::output() const {
    std::string out;
    for (const Pipe* pipe : {&out_, &err_}) {
        for (const std::string& line : pipe->lines) {
            out += line + "\n";
        }
    }
    return out;
}

} // namespace carrom::test_support
