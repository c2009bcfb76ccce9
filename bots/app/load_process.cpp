#include "load_process.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace carrom::load {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

// Starts the server on 127.0.0.1 with an ephemeral port and reads its "listening on" line.
std::optional<SpawnedServer> spawn_server(const std::string& binary,
                                          const std::vector<std::string>& extra) {
    int out[2];
    if (pipe(out) != 0) {
        return std::nullopt;
    }
    const pid_t pid = fork();
    if (pid < 0) {
        return std::nullopt;
    }
    if (pid == 0) {
        dup2(out[1], STDOUT_FILENO);
        close(out[0]);
        close(out[1]);
        // Every load client connects from 127.0.0.1.
        std::vector<std::string> args = {
            binary,   "--host",      "127.0.0.1", "--port",
            "0",      "--log-level", "warn",      "--max-connections-per-address",
            "1000000"};
        // No match store unless a --server-arg names one (--data PATH).
        if (std::find(extra.begin(), extra.end(), "--data") == extra.end()) {
            args.insert(args.end(), {"--data", "none"});
        }
        args.insert(args.end(), extra.begin(), extra.end());
        std::vector<char*> argv;
        for (auto& a : args) {
            argv.push_back(a.data());
        }
        argv.push_back(nullptr);
        execv(binary.c_str(), argv.data());
        _exit(127);
    }
    close(out[1]);
    FILE* in = fdopen(out[0], "r");
    char line[256];
    SpawnedServer server{pid, 0};
    while (in && std::fgets(line, sizeof line, in)) {
        unsigned port = 0;
        if (std::sscanf(line, "listening on 127.0.0.1:%u", &port) == 1) {
            server.port = static_cast<std::uint16_t>(port);
            break;
        }
    }
    // Keep draining its stdout so the server never blocks on a full pipe.
    std::thread([in] {
        char sink[256];
        while (in && std::fgets(sink, sizeof sink, in)) {
        }
        if (in) {
            std::fclose(in);
        }
    }).detach();
    if (server.port == 0) {
        kill(pid, SIGKILL);
        waitpid(pid, nullptr, 0);
        return std::nullopt;
    }
    return server;
}

// VmRSS of a process, KiB (0 if unreadable).
long rss_kib(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string key;
    while (status >> key) {
        if (key == "VmRSS:") {
            long value = 0;
            status >> value;
            return value;
        }
        status.ignore(1 << 12, '\n');
    }
    return 0;
}

// utime + stime of a process, seconds.
double cpu_seconds(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
    const auto close = text.rfind(')');
    if (close == std::string::npos) {
        return 0.0;
    }
    std::istringstream fields(text.substr(close + 2));
    std::string field;
    double ticks = 0.0;
    for (int i = 3; i <= 15 && fields >> field; ++i) {
        if (i == 14 || i == 15) {
            ticks += std::stod(field);
        }
    }
    return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// GET /metrics as name -> value (histogram buckets keep their label in the name).
std::map<std::string, double> fetch_metrics(std::uint16_t port) {
    std::map<std::string, double> values;
    try {
        asio::io_context ioc;
        tcp::socket socket(ioc);
        socket.connect({asio::ip::make_address("127.0.0.1"), port});
        const std::string request =
            "GET /metrics HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
        asio::write(socket, asio::buffer(request));
        std::string response;
        boost::system::error_code ec;
        asio::read(socket, asio::dynamic_buffer(response), ec);
        std::istringstream lines(response.substr(response.find("\r\n\r\n") + 4));
        std::string line;
        while (std::getline(lines, line)) {
            if (line.empty() || line[0] == '#') {
                continue;
            }
            const auto space = line.rfind(' ');
            if (space != std::string::npos) {
                values[line.substr(0, space)] = std::stod(line.substr(space + 1));
            }
        }
    } catch (const std::exception&) {
    }
    return values;
}

} // namespace carrom::load
