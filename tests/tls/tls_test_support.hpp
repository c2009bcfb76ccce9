#pragma once
// What the TLS tests share: the certificates make_test_pki.sh makes in a temporary directory,
// carrom-server with one of them, carrom-bot runs with their JSON summaries, and the serial
// number of the certificate a new TLS connection is given.

#include "support/child_process.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace carrom::tls_test {

// The test PKI (make_test_pki.sh lists the files): ca.pem, server.pem/.key (localhost and
// 127.0.0.1), renewed.pem/.key, localhost.pem/.key, expired.pem/.key, other-ca.pem.
class Pki {
public:
    Pki();
    bool made() const { return made_; }
    std::string file(const std::string& name) const { return dir_.file(name); }
    // Copies NAME.pem and NAME.key to live.pem and live.key, the files a server is given (so a
    // test can replace them and send SIGHUP).
    void make_live(const std::string& name) const;

private:
    test_support::TempDir dir_{"carrom_tls"};
    bool made_ = false;
};

// carrom-server on 127.0.0.1 with live.pem and live.key, `args` and --data `data`.
std::unique_ptr<test_support::ServerProcess> start_tls_server(const Pki& pki,
                                                              std::vector<std::string> args = {},
                                                              const std::string& data = "none");

// carrom-bot's argv: --url URL, its timeout, then `args`.
std::vector<std::string> bot_argv(const std::string& url, std::vector<std::string> args);

// A carrom-bot run to its end (at most `timeout_s` + 10 s): exit code and the JSON summary
// (null when none came).
struct BotRun {
    int exit = -1;
    nlohmann::json summary;
    std::string output;
};
BotRun run_bot(const std::string& url, std::vector<std::string> args);
BotRun finish_bot(test_support::ChildProcess& bot);

// The serial number (upper-case hex) of the certificate a new TLS connection to 127.0.0.1:port
// is given, verified with ca_file for `host`; empty when the handshake fails.
std::string served_serial(std::uint16_t port, const std::string& host, const std::string& ca_file);

// The "tls: {...}" line of /healthz as JSON (null when there is none).
nlohmann::json health_tls(const test_support::ServerProcess& server);

} // namespace carrom::tls_test
