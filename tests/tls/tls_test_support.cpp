#include "tls_test_support.hpp"

#include "support/command_run.hpp"

#include "carrom/tls/client_tls.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <openssl/ssl.h>

#include <chrono>
#include <filesystem>
#include <sstream>

namespace carrom::tls_test {

namespace asio = boost::asio;
namespace beast = boost::beast;
using Clock = std::chrono::steady_clock;

Pki::Pki() {
    made_ = test_support::run_command(std::string(CARROM_TLS_PKI_SCRIPT) + " " + dir_.path() +
                                      " > /dev/null")
                .exit == 0;
}

void Pki::make_live(const std::string& name) const {
    const auto options = std::filesystem::copy_options::overwrite_existing;
    std::filesystem::copy_file(file(name + ".pem"), file("live.pem.new"), options);
    std::filesystem::copy_file(file(name + ".key"), file("live.key"), options);
    std::filesystem::rename(file("live.pem.new"), file("live.pem"));
}

std::unique_ptr<test_support::ServerProcess>
start_tls_server(const Pki& pki, std::vector<std::string> args, const std::string& data) {
    test_support::ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.data = data;
    options.args = {"--tls-cert", pki.file("live.pem"), "--tls-key", pki.file("live.key")};
    options.args.insert(options.args.end(), args.begin(), args.end());
    auto server = std::make_unique<test_support::ServerProcess>(std::move(options));
    return server;
}

std::vector<std::string> bot_argv(const std::string& url, std::vector<std::string> args) {
    std::vector<std::string> argv{CARROM_BOT_PATH, "--url", url, "--timeout", "30"};
    argv.insert(argv.end(), args.begin(), args.end());
    return argv;
}

BotRun finish_bot(test_support::ChildProcess& bot) {
    BotRun run;
    const auto code = bot.wait_exit(Clock::now() + std::chrono::seconds(40));
    run.exit = code.value_or(-1);
    run.output = bot.output();
    for (const auto& line : bot.lines(test_support::ChildProcess::Stream::Out)) {
        if (!line.empty() && line.front() == '{') {
            run.summary = nlohmann::json::parse(line, nullptr, false);
        }
    }
    return run;
}

BotRun run_bot(const std::string& url, std::vector<std::string> args) {
    test_support::ChildProcess bot(bot_argv(url, std::move(args)));
    return finish_bot(bot);
}

std::string served_serial(std::uint16_t port, const std::string& host, const std::string& ca_file) {
    auto context = tls::client_tls_context(ca_file);
    if (context.index() != 0) {
        return {};
    }
    asio::io_context ioc;
    tls::FlexStream<beast::tcp_stream> stream(ioc);
    beast::error_code ec;
    beast::get_lowest_layer(stream).expires_after(std::chrono::seconds(5));
    beast::get_lowest_layer(stream).socket().connect({asio::ip::make_address("127.0.0.1"), port},
                                                     ec);
    tls::VerifyFailure failure;
    if (ec || !tls::start_client_tls(stream, std::get<0>(context), host, failure)) {
        return {};
    }
    std::string serial;
    stream.tls().async_handshake(asio::ssl::stream_base::client, [&](beast::error_code e) {
        if (!e) {
            X509* certificate = SSL_get1_peer_certificate(stream.tls().native_handle());
            serial = tls::certificate_facts(certificate).serial;
            X509_free(certificate);
        }
    });
    ioc.run();
    return serial;
}

nlohmann::json health_tls(const test_support::ServerProcess& server) {
    std::istringstream lines(server.get("/healthz").body);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("tls: ", 0) == 0) {
            return nlohmann::json::parse(line.substr(5), nullptr, false);
        }
    }
    return nullptr;
}

} // namespace carrom::tls_test
