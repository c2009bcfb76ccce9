#include "support/server_process.hpp"

#include "support/read_file.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <thread>
#include <utility>

namespace carrom::test_support {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

ServerProcess::ServerProcess(Options options)
    : options_(std::move(options)), log_dir_("carrom_server_log"),
      log_path_(log_dir_.file("stderr.log")), port_(options_.port) {
    start();
}

ServerProcess::~ServerProcess() {
    if (process_) {
        process_->stop();
    }
}

bool ServerProcess::start() {
    if (process_) {
        process_->stop();
    }
    log_start_ = read_file(log_path_).size();
    std::vector<std::string> argv{options_.program,      "--host", "127.0.0.1",  "--port",
                                  std::to_string(port_), "--data", options_.data};
    // Tests read the match API and /metrics far faster than the per-address default allows.
    argv.insert(argv.end(), {"--http-rate", "1000", "--http-burst", "1000"});
    argv.insert(argv.end(), options_.args.begin(), options_.args.end());
    process_ = std::make_unique<ChildProcess>(argv, options_.env, log_path_);
    const auto deadline = Clock::now() + 15s;
    const std::string prefix = "listening on 127.0.0.1:";
    const auto line = process_->wait_line(ChildProcess::Stream::Out, prefix, deadline);
    if (!line) {
        return false;
    }
    const int port = std::stoi(line->substr(prefix.size()));
    if (port_ != 0 && port != port_) {
        return false;
    }
    port_ = static_cast<std::uint16_t>(port);
    while (Clock::now() < deadline) {
        if (get("/healthz").status != 0) {
            return true;
        }
        std::this_thread::sleep_for(20ms);
    }
    return false;
}

void ServerProcess::kill9() {
    process_->kill_now();
}

void ServerProcess::terminate(std::chrono::milliseconds grace) {
    process_->stop(grace);
}

std::string ServerProcess::url() const {
    return "ws://127.0.0.1:" + std::to_string(port_);
}

std::string ServerProcess::base() const {
    return "http://127.0.0.1:" + std::to_string(port_);
}

ServerProcess::Http ServerProcess::get(const std::string& target) const {
    Http answer;
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) {
        return answer;
    }
    timeval timeout{5, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &timeout, sizeof timeout);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port_);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    std::string bytes;
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0) {
        const std::string request = "GET " + target + " HTTP/1.0\r\nHost: localhost\r\n\r\n";
        std::size_t sent = 0;
        while (sent < request.size()) {
            const ssize_t n =
                ::send(fd, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
            if (n <= 0) {
                break;
            }
            sent += static_cast<std::size_t>(n);
        }
        char buffer[16384];
        ssize_t got = 0;
        while (sent == request.size() && (got = ::recv(fd, buffer, sizeof buffer, 0)) > 0) {
            bytes.append(buffer, static_cast<std::size_t>(got));
        }
    }
    ::close(fd);
    const auto end = bytes.find("\r\n\r\n");
    if (bytes.rfind("HTTP/1.", 0) != 0 || bytes.size() < 12 || end == std::string::npos) {
        return answer;
    }
    answer.status = std::stoi(bytes.substr(9, 3));
    answer.body = bytes.substr(end + 4);
    return answer;
}

std::string ServerProcess::log() const {
    return read_file(log_path_);
}

std::string ServerProcess::log_of_this_start() const {
    const std::string all = log();
    return all.size() > log_start_ ? all.substr(log_start_) : std::string();
}

std::optional<std::string> ServerProcess::wait_log(const std::string& needle,
                                                   Clock::time_point deadline) const {
    for (;;) {
        const std::string text = log_of_this_start();
        const auto at = text.find(needle);
        if (at != std::string::npos) {
            const auto begin = text.rfind('\n', at);
            const auto from = begin == std::string::npos ? 0 : begin + 1;
            const auto to = text.find('\n', at);
            return text.substr(from, to == std::string::npos ? std::string::npos : to - from);
        }
        if (Clock::now() >= deadline) {
            return std::nullopt;
        }
        std::this_thread::sleep_for(20ms);
    }
}

} // namespace carrom::test_support
