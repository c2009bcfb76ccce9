// Connections that never finish a TLS handshake harm nothing (docs/tls.md): with
// --tls-handshake-timeout 0.5 and --max-connections-per-address 8, TCP connections from
// 127.0.0.2 that send nothing or stop in the middle of a ClientHello hold at most 8 sockets,
// are closed by the server when the timeout passes, and a flood of them is closed at once beyond
// the 8; meanwhile clients from 127.0.0.1 get their handshakes and /healthz at once.
#include "tls_test_support.hpp"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <thread>

namespace carrom::tls_test {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// The start of a ClientHello record (a handshake record of 512 bytes holding a ClientHello of
// 508), of which only these few bytes ever come: enough for the server to take it for TLS and
// begin the handshake (Beast's detection reads 9 bytes), never enough to finish it.
constexpr unsigned char kClientHelloStart[] = {0x16, 0x03, 0x01, 0x02, 0x00,
                                               0x01, 0x00, 0x01, 0xFC};

// A TCP connection from `source` to 127.0.0.1:port (-1 when it failed).
int connect_from(const char* source, std::uint16_t port) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in from{};
    from.sin_family = AF_INET;
    inet_pton(AF_INET, source, &from.sin_addr);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(port);
    inet_pton(AF_INET, "127.0.0.1", &to.sin_addr);
    if (fd < 0 || bind(fd, reinterpret_cast<sockaddr*>(&from), sizeof from) != 0 ||
        connect(fd, reinterpret_cast<sockaddr*>(&to), sizeof to) != 0) {
        if (fd >= 0) {
            close(fd);
        }
        return -1;
    }
    return fd;
}

// True when the server closed fd (end of stream or reset) within `wait`.
bool closed_within(int fd, std::chrono::milliseconds wait) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(wait.count())) != 1) {
        return false;
    }
    char byte = 0;
    return read(fd, &byte, 1) <= 0;
}

// A counter of /metrics (-1 when missing).
long metric(const test_support::ServerProcess& server, const std::string& name) {
    const std::string body = server.get("/metrics").body;
    const auto at = body.find("\n" + name + " ");
    return at == std::string::npos ? -1 : std::stol(body.substr(at + name.size() + 2));
}

class TlsFlood : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(pki_.made());
        pki_.make_live("server");
        server_ = start_tls_server(
            pki_, {"--tls-handshake-timeout", "0.5", "--max-connections-per-address", "8"});
        ASSERT_NE(server_->port(), 0);
    }
    void TearDown() override {
        for (const int fd : fds_) {
            close(fd);
        }
    }
    // Opens a connection from 127.0.0.2 that sends `hello_start` bytes of a ClientHello.
    int open_stalled(std::size_t hello_start) {
        const int fd = connect_from("127.0.0.2", server_->port());
        EXPECT_GE(fd, 0);
        if (fd >= 0) {
            fds_.push_back(fd);
            if (hello_start > 0) {
                EXPECT_EQ(write(fd, kClientHelloStart, hello_start),
                          static_cast<ssize_t>(hello_start));
            }
        }
        return fd;
    }

    Pki pki_;
    std::unique_ptr<test_support::ServerProcess> server_;
    std::vector<int> fds_;
};

TEST_F(TlsFlood, HalfOpenConnectionsAreClosedByTheHandshakeTimeout) {
    const auto opened = Clock::now();
    std::vector<int> held;
    for (int i = 0; i < 4; ++i) {
        held.push_back(open_stalled(0));                        // never a byte
        held.push_back(open_stalled(sizeof kClientHelloStart)); // stops inside the ClientHello
    }
    std::this_thread::sleep_for(100ms); // the server has counted them
    const int ninth = open_stalled(0);
    EXPECT_TRUE(closed_within(ninth, 300ms)) << "over the address's limit: closed at once";
    // Another address is not limited by these: its handshake and /healthz answer at once.
    const auto other = Clock::now();
    EXPECT_EQ(served_serial(server_->port(), "127.0.0.1", pki_.file("ca.pem")), "1001");
    EXPECT_EQ(server_->get("/healthz").status, 200);
    EXPECT_LT(Clock::now() - other, 400ms);
    for (const int fd : held) {
        EXPECT_TRUE(closed_within(fd, 2s));
    }
    EXPECT_GE(Clock::now() - opened, 450ms) << "closed by the timeout, not before";
    EXPECT_GE(metric(*server_, "carrom_tls_handshake_failures_total"), 4);
    // The address's count is back to 0: a new connection from it is served.
    const int later = open_stalled(0);
    EXPECT_FALSE(closed_within(later, 200ms));
}

TEST_F(TlsFlood, FloodBeyondTheLimitIsClosedAtOnce) {
    const long rejected_before = metric(*server_, "carrom_rejected_connections_total");
    for (int i = 0; i < 200; ++i) {
        open_stalled(sizeof kClientHelloStart);
    }
    const auto during = Clock::now();
    EXPECT_EQ(served_serial(server_->port(), "localhost", pki_.file("ca.pem")), "1001");
    EXPECT_EQ(server_->get("/healthz").status, 200);
    EXPECT_LT(Clock::now() - during, 400ms);
    int closed = 0;
    for (std::size_t i = 8; i < fds_.size(); ++i) {
        closed += closed_within(fds_[i], 50ms) ? 1 : 0;
    }
    EXPECT_EQ(closed, 192);
    EXPECT_EQ(metric(*server_, "carrom_rejected_connections_total") - rejected_before, 192);
    // Many whole handshakes in a row from 127.0.0.1 meanwhile.
    for (int i = 0; i < 20; ++i) {
        ASSERT_EQ(served_serial(server_->port(), "127.0.0.1", pki_.file("ca.pem")), "1001");
    }
}

} // namespace
} // namespace carrom::tls_test
