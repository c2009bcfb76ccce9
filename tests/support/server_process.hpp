#pragma once
// carrom-server as a program for tests: on 127.0.0.1 with a port (0: an ephemeral one, kept
// for restarts), a --data value and the caller's further options; started means its "listening
// on" line came and GET /healthz answers. kill9() (no shutdown of its own: a crash),
// terminate() (SIGTERM: its orderly shutdown), restart() on the same port and data. Its stderr
// goes to a file of its own (every start appended), for failure messages and its log lines.

#include "support/child_process.hpp"
#include "support/temp_dir.hpp"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace carrom::test_support {

class ServerProcess {
public:
    struct Options {
        std::string program;           // carrom-server's path (CARROM_SERVER_PATH)
        std::string data = "none";     // --data: the store's file, or "none"
        std::vector<std::string> args; // more options, after --host, --port and --data
        std::vector<std::string> env;  // "NAME=value" entries for its environment
        std::uint16_t port = 0;        // 0: an ephemeral port
    };
    // One plain HTTP/1.0 answer; status 0 when none came.
    struct Http {
        int status = 0;
        std::string body;
    };

    // Starts the server (see start()).
    explicit ServerProcess(Options options);
    ~ServerProcess();
    ServerProcess(const ServerProcess&) = delete;
    ServerProcess& operator=(const ServerProcess&) = delete;

    // Starts it (ending a running one first with SIGTERM) and waits up to 15 s for its
    // "listening on 127.0.0.1:PORT" line and a /healthz answer; true when both came. The first
    // start learns the port, later ones ask for the same one.
    bool start();
    // Kills it at once (SIGKILL): nothing of its own shutdown runs.
    void kill9();
    // SIGTERM, then SIGKILL after `grace`: its own orderly shutdown.
    void terminate(std::chrono::milliseconds grace = std::chrono::seconds(10));
    // start() again on the same port and data, after kill9() or terminate().
    bool restart() { return start(); }

    std::uint16_t port() const { return port_; }
    std::string url() const;  // ws://127.0.0.1:PORT
    std::string base() const; // http://127.0.0.1:PORT
    ChildProcess& process() { return *process_; }

    // GET `target` (e.g. "/matches/ID") on 127.0.0.1:port() as HTTP/1.0; 5 s at most.
    Http get(const std::string& target) const;

    // Everything it wrote on stderr, every start.
    std::string log() const;
    // What it wrote on stderr since the latest start.
    std::string log_of_this_start() const;
    // The first line of this start's stderr holding `needle`, waiting for it until `deadline`.
    std::optional<std::string> wait_log(const std::string& needle,
                                        std::chrono::steady_clock::time_point deadline) const;

private:
    Options options_;
    TempDir log_dir_;
    std::string log_path_;
    std::size_t log_start_ = 0; // the log's size when the latest start began
    std::unique_ptr<ChildProcess> process_;
    std::uint16_t port_ = 0;
};

} // namespace carrom::test_support
